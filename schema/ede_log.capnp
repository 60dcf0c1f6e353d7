# The messages of an ede event log (.ede), format versions 1, 2 and 3. The framing around them (file header,
# record headers, zstd frames, trailer) and the column encodings are described in FORMAT.md beside this
# file. Every scalar of the simulation (times, positions, velocities, radii, masses) is stored as the raw
# little-endian bytes of the run's scalar type, so a log is exact for float, double and long double runs.
@0xd658984db1cc87ad;

using Cxx = import "/capnp/c++.capnp";
$Cxx.namespace("ede::logschema");

enum ScalarType {
  float32 @0;   # IEEE binary32, 4 bytes
  float64 @1;   # IEEE binary64, 8 bytes
  float80 @2;   # x87 extended precision, 10 bytes (the 80 significant bits of a long double)
}

enum Boundary {
  walls @0;
  periodic @1;
  leesEdwards @2;  # format version 3: periodic, the images above and below sliding (the scene's box.shear_rate)
}

# The first record: what was run, by what, and the per-disk constants.
struct Header {
  engineVersion @0 :Text;
  compiler @1 :Text;          # e.g. "GCC 12.2.0"
  compileFlags @2 :Text;      # the flags that matter for floating point
  scalar @3 :ScalarType;
  seed @4 :UInt64;
  sceneName @5 :Text;         # the scene file's name when it was run
  sceneText @6 :Text;         # the effective scene (TOML, after --set overrides): exactly what was run
  diskCount @7 :UInt32;
  speciesNames @8 :List(Text);
  boxX @9 :Float64;
  boxY @10 :Float64;
  boundary @11 :Boundary;
  chunkEvents @12 :UInt32;        # events per chunk (the last chunk before a keyframe or the end may hold fewer)
  keyframeInterval @13 :UInt64;   # logged events between keyframes
  rebuildInterval @14 :UInt64;    # engine events between rebuilds (resumable keyframes)
  radius @15 :Data;               # diskCount scalars
  mass @16 :Data;                 # diskCount scalars
  species @17 :List(UInt32);      # diskCount species indices
  initialEnergy @18 :Float64;     # kinetic energy at t = 0
  tcModel @19 :Bool;              # the run keeps TC collision times (keyframes carry them)
  columnEncoding @20 :UInt32;     # version of the chunk column encodings (FORMAT.md): 1, or 2 in format version 2
  gravityX @21 :Float64;          # constant gravity (0 when absent: logs written before it read as no gravity)
  gravityY @22 :Float64;
  # Format version 2: the collision rules' constants, as the engine holds them (scalars of the run's type),
  # for replay's predictions of post-collision velocities (FORMAT.md, "Predictions").
  pairOnePlusXi @23 :Data;        # S x S scalars, S = max(1, speciesNames): 1 + xi of species pair (a, b) at a S + b
  wallRestitution @24 :Data;      # 4 scalars: xi of the left, right, bottom and top walls
  # The run id (FORMAT.md, "Run id"): a digest of this header without the build's fields; every chunk and
  # keyframe repeats it, so records of another run spliced behind this header are refused. 0: not recorded
  # (logs written before it), then nothing is checked.
  runId @25 :UInt32;
  # Rough disks (FORMAT.md, "Rotation"): only a run whose disks carry an angular velocity writes these
  # (its header is then built with them; every other run's header keeps its earlier size and bytes).
  inertia @26 :Data;              # diskCount scalars, byte-plane shuffled: each disk's moment of inertia
  onePlusBeta @27 :Data;          # S x S + 4 scalars: 1 + beta of species pair (a, b) at a S + b, then of the 4 walls
}

# A run of consecutive logged events, stored as columns (FORMAT.md, "Chunk columns").
struct Chunk {
  firstEvent @0 :UInt64;   # index of the chunk's first event in the log (0-based)
  count @1 :UInt32;
  times @2 :Data;          # event times
  kinds @3 :Data;          # one byte per event: 0 pair, 1 wall, 3 wrap, 4 action, 6 segment, 8 thermostat (encoding 3)
                           # (ede::EventKind); encoding 2 and 3: + 16 if TC-elastic
  disks @4 :Data;          # the first disk i of pair, wall and wrap events
  partners @5 :Data;       # pair: j - i; wall: wall id; wrap: direction
  velocitiesRaw @6 :Data;        # encoding 1, pair: v_i' as raw scalars, byte-plane shuffled; encoding 2: empty;
                                 # encoding 3: a thermostat event's v' as raw scalars, byte-plane shuffled
  velocityResiduals @7 :Data;    # encoding 1: pair v_j' against momentum, wall v' against reflection;
                                 # encoding 2: pair v_i', v_j' and wall v' against the collision rules
  runId @8 :UInt32;              # the header's runId (0 in logs written before it)
  spinResiduals @9 :Data;        # rough runs only: pair w_i', w_j' and wall w' against the rough rule (FORMAT.md)
}

# The full state after a given number of logged events.
struct Keyframe {
  eventsBefore @0 :UInt64;     # logged events before this state (the chunk after it starts there)
  time @1 :Data;               # one scalar: the time of the state (every disk's record is valid from its own t)
  resumable @2 :Bool;          # taken at an engine rebuild: a run can continue from here bit for bit
  x @3 :Data;                  # per disk, raw scalars: position at the disk's own time t
  y @4 :Data;
  vx @5 :Data;
  vy @6 :Data;
  t @7 :Data;
  lastPartner @8 :List(Int32);  # resumable keyframes: the engine's last-partner ids
  lastCollision @9 :Data;       # resumable keyframes of TC runs: each disk's last collision time
  engineCounts @10 :List(UInt64);  # resumable: engine counters by EventKind 0-5, then stale, then tcElastic, then
                                   # segment (runs with segments); version 3: always segment, step, then thermostat (its runs
                                   # and Lees-Edwards ones), then shear (Lees-Edwards runs)
  nextSample @11 :UInt64;       # resumable: samples already taken
  nextAction @12 :UInt64;       # resumable: actions already done
  sameTimeEvents @13 :UInt64;   # resumable: the stall detector's count
  runId @14 :UInt32;            # the header's runId (0 in logs written before it)
  omega @15 :Data;              # rough runs only: per disk, raw scalars, byte-plane shuffled: angular velocity
}

# The last record: where every chunk and keyframe is, and how the run ended.
struct Index {
  entries @0 :List(Entry);
  struct Entry {
    kind @0 :UInt8;          # record kind (FORMAT.md): 2 chunk, 3 keyframe
    offset @1 :UInt64;       # file offset of the record header
    firstEvent @2 :UInt64;   # chunk: its first event; keyframe: eventsBefore
    count @3 :UInt64;        # chunk: its events; keyframe: 0
    timeFirst @4 :Float64;   # the time span (as double, for seeking; exact times are in the records)
    timeLast @5 :Float64;
    resumable @6 :Bool;
  }
  totalEvents @1 :UInt64;
  finalTime @2 :Data;        # one scalar: the time the run reached
  status @3 :Text;           # why it ended
}
