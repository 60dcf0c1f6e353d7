#include "run/log_run_info.hpp"

#include "scene/scene_label.hpp"

namespace ede {

LogRunInfo log_run_info(const Scene& scene, const EngineOptions& options, const std::vector<std::string>& species) {
  LogRunInfo r;
  r.scene_name = scene_label(scene.source_name);  // not the directory: same scene, same bytes
  r.scene_text = scene.source_text;
  r.seed = scene.seed;
  r.scalar = scene.scalar;
  r.species_names = species;
  r.lx = scene.lx;
  r.ly = scene.ly;
  r.boundary = options.boundary;
  r.rebuild_interval = options.rebuild_interval;
  r.tc_model = uses_tc_model(options.physics);
  r.gx = options.physics.gravity[0];
  r.gy = options.physics.gravity[1];
  r.set_restitution(options.physics);
  r.rotation = uses_rotation(options);
  r.thermostat = uses_thermostat(options);
  r.shear = uses_shear(options);
  r.steps = options.physics.has_steps();
  r.engine_constants = true;
  return r;
}

}  // namespace ede
