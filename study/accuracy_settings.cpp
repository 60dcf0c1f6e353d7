// The accuracy study's settings and scene loading; see accuracy_settings.hpp.
#include "study/accuracy_settings.hpp"

#include "ede/scene.hpp"
#include "study/measurement.hpp"

namespace ede::study {

const char* precision_name(Precision p) {
  switch (p) {
    case Precision::Float: return "float";
    case Precision::Double: return "double";
    case Precision::LongDouble: return "long double";
    case Precision::Float128: return "__float128";
  }
  return "?";
}

bool precision_built(Precision p) {
#if EDE_HAVE_FLOAT128
  (void)p;
  return true;
#else
  return p != Precision::Float128;
#endif
}

bool has_log(Precision p) { return p != Precision::Float128; }

std::string Setting::label() const {
  return std::string(precision_name(precision)) + (contact == ContactRoot::Textbook ? ", textbook root" : "");
}

std::vector<Setting> study_settings() {
  std::vector<Setting> all;
  for (const ContactRoot c : {ContactRoot::Stable, ContactRoot::Textbook})
    for (const Precision p : {Precision::Float, Precision::Double, Precision::LongDouble, Precision::Float128})
      if (precision_built(p) && (c == ContactRoot::Stable || p != Precision::Float128)) all.push_back({p, c});
  return all;
}

std::string scalar_override(Precision p) {
  return p == Precision::Float        ? "engine.scalar=float"
         : p == Precision::LongDouble ? "engine.scalar=\"long double\""
         : p == Precision::Float128   ? "engine.scalar=float128"
                                      : "engine.scalar=double";
}

Result<StudyScene> load_study_scene(const std::string& path, const Setting& setting,
                                    std::vector<std::string> overrides) {
  overrides.push_back(scalar_override(setting.precision));
  auto scene = load_scene_file(path, as_overrides(overrides));
  if (!scene) return scene.error();
  auto plan = plan_run(scene.value());
  if (!plan) return plan.error();
  StudyScene s{std::move(plan.value().scene), std::move(plan.value().initial), plan.value().options, {}};
  s.variant.contact = setting.contact;
  return s;
}

}  // namespace ede::study
