// The Scene: everything a run needs, as plain data, before any particle exists.
//
// A Scene is what a scene file (TOML, see docs/scene-format.md) says after overrides and validation. All
// numbers are doubles here whatever scalar type the engine later runs in: setup draws the initial state in
// double, so float, double and long double runs of one scene start from the same disks (up to rounding).
// Rejected: letting the TOML tree flow into setup and the engine; every consumer would re-check types.
//
// Loading (load_scene_file, parse_scene_text): TOML text -> --set overrides -> checked Scene. Every error
// names the file, the line and column where the TOML parser knows them, the key as a dotted path
// (species[1].radius), what is wrong and what would fix it. Unknown keys are errors (no silent default
// for a mistyped key). Overrides are applied to the TOML tree before checking, so an override is checked
// exactly like the file's own value, and Scene::source_text records what was run.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ede/error.hpp"

namespace ede {

enum class BoundaryKind { Walls, Periodic };
// The engine's scalar type. Float128 is __float128 (GCC's libquadmath), only where the library was built with
// EDE_HAVE_FLOAT128, and for the engine only: a log holds one of the other three. Append only: a log's
// content digest hashes the value.
enum class ScalarKind { Float, Double, LongDouble, Float128 };

struct Region {  // axis-aligned rectangle [x0, x1] x [y0, y1]
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  double area() const { return width() * height(); }
};

struct RadiusSpec {  // fixed when min == max, else uniform in [min, max]
  double min = 0;
  double max = 0;
  bool from_packing = false;  // radius not given: set from placement.packing_fraction
};

struct MassSpec {
  enum class Kind { Fixed, PerArea } kind = Kind::Fixed;
  double value = 1;  // the mass, or the areal density (mass = value * pi * r^2)
};

enum class PlacementKind { Random, Lattice, Explicit };
enum class LatticeKind { Hexagonal, Square };
// How random placement draws its candidates (both are random sequential addition, the same law of the
// placed positions): over the whole region (the default, the positions of every earlier version), or, once
// most of the region is blocked, only from voxels not yet wholly blocked (faster near jamming, other positions).
enum class RandomSampling { Region, FreeVoxels };

struct PlacementSpec {
  PlacementKind kind = PlacementKind::Random;
  Region region;                            // random and lattice: where the disks go (whole disks inside)
  std::optional<double> packing_fraction;   // random and lattice: sets the radius (count disks fill it)
  LatticeKind lattice = LatticeKind::Hexagonal;
  RandomSampling sampling = RandomSampling::Region;  // random only
  std::vector<std::array<double, 2>> positions;  // explicit: one [x, y] per disk
};

enum class VelocityKind { Zero, Speed, Vector, Maxwell, List };

struct VelocitySpec {
  VelocityKind kind = VelocityKind::Zero;
  double speed = 0;                          // Speed: |v| for every disk, direction uniform at random
  std::array<double, 2> vector{0, 0};        // Vector: the same v for every disk
  double temperature = 0;                    // Maxwell: kT (k = 1), each component ~ N(0, kT/m)
  std::vector<std::array<double, 2>> list;   // List: one [vx, vy] per disk
};

// The initial angular velocity of a species' disks (rough disks, docs/physics.md): zero, one value for
// every disk, or drawn per disk, omega ~ N(0, kT / I), from the species' own random stream after its
// velocities (so a scene's velocities do not change when spin is added).
struct SpinSpec {
  enum class Kind { Zero, Value, Maxwell } kind = Kind::Zero;
  double omega = 0;        // Value
  double temperature = 0;  // Maxwell: kT of the rotation (k = 1)
};

// Where a value stands in the scene's file, for the errors setup finds after loading (an overlap in an
// explicit list, a lattice too small for its disks), which name FILE:LINE:COL and the key like the
// loader's own: line and column from 1, or 0 when the value did not come from the file (--set, code).
struct SourceSpot {
  std::uint32_t line = 0, column = 0;
};

// The Andersen thermostat ([thermostat], or [species.thermostat] for one species; docs/scene-format.md,
// docs/physics.md): each disk it covers has its velocity redrawn from Maxwell-Boltzmann at kT
// (each component ~ N(0, kT/m)) at the times of a Poisson process of rate `rate` (per disk, per unit time).
struct ThermostatSpec {
  double temperature = 1;            // kT (Boltzmann's constant is 1)
  double rate = 0;                   // redraws per disk per unit time; 0: the disks are not thermostatted
  std::vector<std::string> species;  // [thermostat] only: the species it covers (empty: every species)
};

struct SpeciesSpec {
  std::string name;
  std::int64_t count = 0;
  RadiusSpec radius;
  MassSpec mass;
  PlacementSpec placement;
  VelocitySpec velocity;
  double inertia_factor = 0.5;  // moment of inertia I = inertia_factor * m r^2 (0.5: a uniform disk)
  SpinSpec spin;
  std::optional<ThermostatSpec> thermostat;  // [species.thermostat]: this species' own, instead of [thermostat]
  SourceSpot spot, count_spot;            // its [[species]] table and its count (else the table) in the file
  std::vector<SourceSpot> position_spots;  // explicit placement: each [x, y] (empty: not from a file)
};

struct StopSpec {  // the run ends at the first condition met; at least one must be given
  std::optional<double> time;                     // simulated time
  std::optional<std::uint64_t> events;            // processed events of every kind but samples
  std::optional<double> collisions_per_particle;  // 2 * (pair collisions) / N
  std::optional<double> energy_fraction;          // kinetic energy <= fraction * initial
};

enum class ActionKind { ReverseVelocities };

// An action happens at a time, or (collisions_per_disk set, time 0) right after the pair collision at
// which the collisions per disk, 2 P / N with P the pair collisions so far, first reach the value:
// the first P with 2 P >= k N (in double), at that collision's time, before any other event.
struct ActionSpec {
  double time = 0;
  ActionKind kind = ActionKind::ReverseVelocities;
  std::optional<double> collisions_per_disk;
};

struct PairRestitution {  // the restitution between disks of two species (by name), overriding the default
  std::string a, b;
  double value = 1;
  std::optional<double> roughness;  // beta of this pair (rough disks); absent: physics.roughness
};

// A stepped potential between disks of two species (by name; both empty: every pair of species without an
// entry of its own), outside their hard core: at each distance between centres radius[k] (increasing, above
// the largest contact distance of the two species) the potential energy changes by energy[k] on the way in
// (a square well: energy < 0; a square shoulder: energy > 0). docs/scene-format.md, docs/physics.md.
struct PairSteps {
  std::string a, b;
  std::vector<double> radius, energy;
};

// A straight wall segment from `from` to `to` ([walls] in a scene: [[walls.segments]], or the sides of a
// [[walls.polygons]]), inside the box, with its own restitution: disks bounce off its body from either
// side and off its end points (docs/scene-format.md; the rule: engine/collide.hpp).
struct SegmentSpec {
  std::array<double, 2> from{0, 0}, to{0, 0};
  double restitution = 1;
};

enum WallSide { kLeftWall = 0, kRightWall = 1, kBottomWall = 2, kTopWall = 3 };  // the order of ede::WallId

struct PhysicsSpec {
  double restitution = 1;       // xi for pair collisions, in [0, 1]: every pair of species unless in `pairs`
  double wall_restitution = 1;  // xi_w for wall collisions, in [0, 1]: every wall unless in `walls`
  std::array<std::optional<double>, 4> walls;  // per wall (left, right, bottom, top)
  std::vector<PairRestitution> pairs;
  double tc = 0;                       // TC model: a collision within tc of a participant's previous one is elastic
  std::array<double, 2> gravity{0, 0};  // constant acceleration (walls only)
  std::vector<SegmentSpec> segments;    // wall segments inside the box (walls boundary, no gravity)
  // Rough disks (docs/physics.md): the tangential restitution beta in [-1, 1] of pairs and of the box
  // walls. -1 (the default) is smooth: the contact's tangential velocity is kept and nothing rotates;
  // +1 reverses it (perfectly rough, energy conserved with xi = 1).
  double roughness = -1;
  double wall_roughness = -1;
  std::optional<ThermostatSpec> thermostat;  // [thermostat]: the Andersen thermostat for every species (or those listed)
  std::vector<PairSteps> steps;  // square wells and shoulders (empty: hard disks only)

  double wall(int side) const { return walls[std::size_t(side)].value_or(wall_restitution); }
  bool has_gravity() const { return gravity[0] != 0 || gravity[1] != 0; }
  bool has_steps() const { return !steps.empty(); }
  // Every collision elastic: no restitution below 1 anywhere.
  bool elastic() const {
    bool all = restitution == 1;
    for (int w = 0; w < 4; ++w) all = all && wall(w) == 1;
    for (const PairRestitution& p : pairs) all = all && p.value == 1;
    for (const SegmentSpec& s : segments) all = all && s.restitution == 1;
    return all;
  }
  double pair_roughness(const PairRestitution& p) const { return p.roughness.value_or(roughness); }
  // Some contact transfers spin: a beta above -1 for pairs, walls or a pair of species.
  bool rough() const {
    bool any = roughness > -1 || wall_roughness > -1;
    for (const PairRestitution& p : pairs) any = any || pair_roughness(p) > -1;
    return any;
  }
};

struct LogSpec {  // how ede-sim -o writes the event log; never changes the simulation itself
  std::optional<std::uint64_t> keyframe_interval;  // logged events between keyframes (default: see log_writer.hpp)
  std::optional<std::uint32_t> chunk_events;       // events per compressed chunk
  std::optional<int> compression_level;            // zstd level
};

// [start]: the disks come from a state instead of [[species]] (setup/setup_from_csv.hpp, run/run_start.hpp):
// an event log at a time (`from`, `at`), or a CSV state in the format ede-replay --at writes (`csv`). The
// run starts at t = 0 from that state, in this scene's box and physics. On start the run records where it
// came from in its own scene text (so in its log): `at` (the log's end when not given) and `digest`, the
// source log's content digest (Log::content_digest) or an XXH3-128 of the CSV file's bytes; a digest
// already given must match, so a rerun (verify, resume) from a changed source is refused.
// Relative paths are relative to the scene file's folder (the working folder for scene text).
struct StartSpec {
  std::string from;            // an event log (.ede)
  std::optional<double> at;    // the time in that log (default: its end)
  std::string csv;             // or a CSV state (exactly one of from and csv)
  std::string digest;          // "xxh3-128:..." of the source; recorded on start when empty
  bool zero_momentum = false;  // subtract the centre-of-mass velocity from every disk
  bool reverse_velocities = false;  // v -> -v for every disk (after zero_momentum)
};

// [grow]: Lubachevsky-Stillinger growth to a dense disordered start (setup/grow.hpp). The species' radii
// give only the radii's ratios: the disks are placed at a low packing fraction, then grow together, all
// radii by one factor, during an event-driven run of their own (unit masses, kT held at 1), until the
// packing fraction is `packing_fraction` (radii then exactly at it) or the reduced pressure Z = PA/(NkT)
// exceeds `pressure` (jamming: the packing fraction reached is phi_J). Then the species' masses and
// velocity rules apply to the grown positions, and the engine's run starts from them.
struct GrowSpec {
  std::optional<double> packing_fraction;  // target: the disks' area over the box's
  std::optional<double> pressure;          // stop when Z exceeds it (jamming when packing_fraction is absent)
  double rate = 1e-3;                      // d(mean diameter)/dt over the thermal speed sqrt(kT/m)
};

struct Scene {
  std::string source_name;   // file name (or "<text>") for messages
  std::string source_text;   // the effective scene as TOML, after --set overrides: what was run
  std::uint64_t seed = 1;
  double lx = 1, ly = 1;
  BoundaryKind boundary = BoundaryKind::Walls;
  // box.boundary = "lees-edwards": a periodic box (boundary is Periodic) whose images above and below slide
  // in x with velocity +-shear_rate * ly (docs/physics.md, "Lees-Edwards shear"). Absent: not sheared.
  std::optional<double> shear_rate;
  PhysicsSpec physics;
  ScalarKind scalar = ScalarKind::Double;
  // Engine events between rebuilds of every prediction from the state alone: the points a run can be
  // resumed from bit for bit. Part of the run's definition (it changes round-off); 0 = automatic.
  std::uint64_t rebuild_interval = 0;
  LogSpec log;
  std::vector<SpeciesSpec> species;  // empty when the scene has a [start]
  std::optional<StartSpec> start;
  std::optional<GrowSpec> grow;      // dense start by growth (with [[species]] only)
  StopSpec stop;
  std::optional<double> sample_interval;  // observers see the exact state at k * interval, k = 1, 2, ...
  // Or: observers see the state right after the pair collision at which 2 P / N first reaches k * this.
  std::optional<double> sample_collisions;
  std::vector<ActionSpec> actions;        // sorted by time, or all by collisions_per_disk and sorted by it

  // The disks carry an angular velocity: some contact is rough or some species starts spinning. Such a
  // run has omega and I per disk in its state and log; any other run is exactly what it was before.
  bool rotates() const {
    bool any = physics.rough();
    for (const SpeciesSpec& s : species) any = any || s.spin.kind != SpinSpec::Kind::Zero;
    return any;
  }
  // The box has Lees-Edwards (sliding) images above and below: box.boundary = "lees-edwards".
  bool sheared() const { return shear_rate.has_value(); }
  // Some disks are thermostatted: [thermostat], or a species' own with a rate above 0.
  bool thermostatted() const {
    bool any = physics.thermostat.has_value();
    for (const SpeciesSpec& s : species) any = any || (s.thermostat && s.thermostat->rate > 0);
    return any;
  }
};

const char* to_string(BoundaryKind);
const char* to_string(ScalarKind);

// key=value, e.g. "physics.restitution=0.9", "species[1].mass=25", "species.projectile.velocity.vector=[0,-5]".
// The value is a TOML value; a bare word that is not a TOML value is taken as a string (scalar=float).
struct Override {
  std::string text;
};

// A scene from a file (its name appears in messages) or from text, with overrides applied and checked.
Result<Scene> load_scene_file(const std::string& path, const std::vector<Override>& overrides = {});
Result<Scene> parse_scene_text(const std::string& text, const std::string& source_name = "<text>",
                               const std::vector<Override>& overrides = {});

}  // namespace ede
