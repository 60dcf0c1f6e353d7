// Effects: the small policy types an Engine is instantiated with, one per physical option a scene uses.
//
// The engine branches on these with `if constexpr`, so code for an effect a scene does not use is not
// compiled into that scene's engine at all: an elastic gas in a periodic box has no restitution, no TC
// bookkeeping, no energy accounting and no wall code in its event loop. Runtime values (xi, xi_w, tc) are
// read only by the instantiations that use them. make_engine picks the instantiation once, at start.
// Rejected: runtime flags tested per event (cheap, but every effect then costs every scene something, and
// DESIGN.md section 6 asks for "pays nothing"), and virtual policies (a call per event).
#pragma once

namespace ede {

struct WallsBoundary {
  static constexpr bool kPeriodic = false;
  static constexpr const char* kName = "walls";
};
struct PeriodicBoundary {
  static constexpr bool kPeriodic = true;
  static constexpr const char* kName = "periodic";
};

struct Elastic {
  static constexpr bool kInelastic = false;
  static constexpr bool kTc = false;
};
struct Inelastic {
  static constexpr bool kInelastic = true;
  static constexpr bool kTc = false;
};
struct InelasticTc {
  static constexpr bool kInelastic = true;
  static constexpr bool kTc = true;
};

// Fields acting on the disks between events. Without one, disks move in straight lines (drift); with
// uniform gravity (walls only: in a periodic box everything would fall forever), in parabolas, and wall
// and cell-crossing times solve quadratics. Pair times stay those of straight lines: two disks under the
// same g see each other move in a straight line.
struct NoField {
  static constexpr bool kGravity = false;
};
struct UniformGravity {
  static constexpr bool kGravity = true;
};

// The pair contact-time root. Engines always use the stable form (geometry.hpp); the textbook form exists
// only so that ede-bench accuracy can show what it costs in accuracy (EngineOptions::contact).
struct StableContact {
  static constexpr bool kTextbook = false;
};
struct TextbookContact {
  static constexpr bool kTextbook = true;
};

}  // namespace ede
