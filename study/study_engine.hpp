// The engine a study run uses: the library's choice for its scene (make_engine), or a study variant.
//   The textbook contact root: the library's two elastic engines (periodic and walls, no gravity) with
//     TextbookContact instead of the stable root, built here (textbook_engine.cpp) for float, double and
//     long double: what the stable root buys in accuracy (ede-bench accuracy).
//   All effects: the library's WallsGravity engine (walls, dissipation with TC, gravity: every effect
//     compiled in, each doing nothing at its neutral value) for any walled scene: what specialization
//     buys (ede-bench effects). No instantiation of its own: it is one of the library's table.
// Runs with a variant are for the studies only, never for results.
#pragma once

#include <memory>

#include "ede/error.hpp"
#include "ede/internal/engine.hpp"

namespace ede::study {

enum class ContactRoot { Stable, Textbook };

struct EngineVariant {
  ContactRoot contact = ContactRoot::Stable;
  bool all_effects = false;  // walls only, stable root only
};

// Instantiated for float, double, long double and (where built) __float128; the textbook root refuses
// __float128, scenes with gravity and dissipative scenes with an error, as the all-effects engine does
// periodic ones.
template <class T>
Result<std::unique_ptr<EngineApi<T>>> make_study_engine(const InitialState& initial, const EngineOptions& options,
                                                        EngineVariant variant, const ResumePoint<T>* resume = nullptr);

}  // namespace ede::study
