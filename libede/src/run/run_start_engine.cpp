// start_run; see run_plan.hpp. Apart from plan_run (run_plan.cpp) because it instantiates every engine
// (make_engine): whoever plans a run without starting one this way does not link them.
#include "run/log_run_info.hpp"
#include "run/run_plan.hpp"

namespace ede {

namespace {

// Frees the per-disk arrays of a state the engine has copied (the box and the species names stay).
void release_disks(InitialState& s) {
  for (std::vector<double>* v : {&s.x, &s.y, &s.vx, &s.vy, &s.radius, &s.mass, &s.omega, &s.inertia})
    std::vector<double>().swap(*v);
  std::vector<std::int32_t>().swap(s.species);
}

}  // namespace

template <class T>
Result<RunEngine<T>> start_run(RunPlan& plan, const RunLog& log, const Resumption<T>* resume) {
  auto engine = make_engine<T>(plan.initial, plan.options, resume ? &resume->point : nullptr);
  if (!engine) return Error{plan.scene.source_name + ": " + engine.error().message};
  release_disks(plan.initial);
  RunEngine<T> run{std::move(engine).value(), {}};
  if (log.path.empty()) return run;
  if constexpr (kLogScalar<T>) {
    LogSettings settings = LogSettings::from(plan.scene.log);
    if (resume) settings.format_version = resume->format_version;  // a resumed log continues as written
    settings.check_exactness = log.check_exactness;
    auto w = LogWriter<T>::create(log.path, log_run_info(plan.scene, plan.options, plan.initial.species_names),
                                  settings, resume ? &resume->continuation : nullptr);
    if (!w) return Error{w.error().message, ErrorKind::Io};
    run.log = std::move(w).value();
    return run;
  } else {
    return Error{plan.scene.source_name + ": float128 runs write no event log", ErrorKind::Unsupported};
  }
}

template Result<RunEngine<float>> start_run(RunPlan&, const RunLog&, const Resumption<float>*);
template Result<RunEngine<double>> start_run(RunPlan&, const RunLog&, const Resumption<double>*);
template Result<RunEngine<long double>> start_run(RunPlan&, const RunLog&, const Resumption<long double>*);
#if EDE_HAVE_FLOAT128
template Result<RunEngine<__float128>> start_run(RunPlan&, const RunLog&, const Resumption<__float128>*);
#endif

}  // namespace ede
