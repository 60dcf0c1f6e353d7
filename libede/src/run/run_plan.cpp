// plan_run and plan_run_from; see run_plan.hpp. start_run is in run_start_engine.cpp, apart: a program that
// plans a run and makes one engine of its own (ede-bench-elastic) then links no engine of the library's.
#include "run/run_plan.hpp"

#include "run/run_checks.hpp"
#include "run/run_start.hpp"
#include "run/scale_checks.hpp"
#include "setup/setup.hpp"

namespace ede {

Result<RunPlan> plan_run(const Scene& scene) {
  if (scene.start) {
    auto started = start_from_state(scene);
    if (!started) return started.error();
    return plan_run_from(started.value().scene, std::move(started.value().initial));
  }
  if (Status s = check_scene_scales(scene); !s) return s.error();  // before setup computes with them
  auto initial = build_initial_state(scene);
  if (!initial) return initial.error();
  return plan_run_from(scene, std::move(initial).value());
}

Result<RunPlan> plan_run_from(const Scene& scene, InitialState initial) {
  if (Status s = check_run_can_finish(scene, initial); !s) return s.error();
  RunPlan plan{scene, std::move(initial), {}};
  plan.options = engine_options_from(plan.scene, plan.initial.size());
  plan.options.rotation = plan.options.rotation || !plan.initial.omega.empty();  // a spinning state stays rough
  return plan;
}

}  // namespace ede
