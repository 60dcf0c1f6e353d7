// Exact CSV snapshots of a state; see state_csv.hpp.
#include "core/state_csv.hpp"

#include "ede/number_text.hpp"
#include "ede/state.hpp"

#include <cerrno>
#include <cstring>

#if EDE_HAVE_FLOAT128
#include <quadmath.h>
#endif

namespace ede {

namespace {

template <class T>
void put(std::FILE* out, T v) {
  char text[kNumberTextSize];
  std::fwrite(text, 1, std::size_t(put_general(text, v, kExactDigits<T>) - text), out);
}
#if EDE_HAVE_FLOAT128
void put(std::FILE* out, __float128 v) {
  char text[64];
  quadmath_snprintf(text, sizeof text, "%.36Qg", v);
  std::fputs(text, out);
}
#endif

template <class C>
void write_rows(std::FILE* out, const State& s) {
  std::vector<const std::vector<C>*> cols = {&s.x.values<C>(),  &s.y.values<C>(),      &s.vx.values<C>(),
                                             &s.vy.values<C>(), &s.radius.values<C>(), &s.mass.values<C>()};
  if (s.rotates()) cols.insert(cols.end(), {&s.omega.values<C>(), &s.inertia.values<C>()});
  for (std::size_t i = 0; i < s.size(); ++i) {
    const std::int32_t sp = s.species[i];
    std::fprintf(out, "%zu,", i);
    if (sp >= 0 && std::size_t(sp) < s.species_names.size())
      std::fputs(s.species_names[std::size_t(sp)].c_str(), out);
    else
      std::fprintf(out, "%d", sp);
    for (const std::vector<C>* c : cols) {
      std::fputc(',', out);
      put(out, (*c)[i]);
    }
    std::fputc('\n', out);
  }
}

Status close_checked(std::FILE* out, const std::string& path) {
  const bool failed = std::ferror(out) != 0;
  if (std::fclose(out) != 0 || failed)
    return Error{"error while writing '" + path + "': " + std::strerror(errno), ErrorKind::Io};
  return Ok{};
}

}  // namespace

void write_state_csv(std::FILE* out, const State& s) {
  std::fputs(s.rotates() ? "id,species,x,y,vx,vy,radius,mass,omega,inertia\n" : "id,species,x,y,vx,vy,radius,mass\n", out);
  switch (s.x.scalar()) {
    case ScalarKind::Float: return write_rows<float>(out, s);
    case ScalarKind::Double: return write_rows<double>(out, s);
    default: return write_rows<long double>(out, s);
  }
}

Status write_state_csv(const std::string& path, const State& s) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) return Error{"cannot write '" + path + "': " + std::strerror(errno), ErrorKind::Io};
  write_state_csv(out, s);
  return close_checked(out, path);
}

template <class T>
void write_state_csv(std::FILE* out, const Particles<T>& p, T time, const std::vector<std::string>& species_names) {
  std::fputs(p.omega.empty() ? "id,species,x,y,vx,vy,radius,mass\n" : "id,species,x,y,vx,vy,radius,mass,omega,inertia\n", out);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Disk<T>& d = p.disk[i];
    const std::int32_t s = p.species_of(i);
    std::fprintf(out, "%zu,", i);
    if (s >= 0 && std::size_t(s) < species_names.size())
      std::fputs(species_names[std::size_t(s)].c_str(), out);
    else
      std::fprintf(out, "%d", s);
    for (T v : {p.x_at(i, time), p.y_at(i, time), p.vx_at(i, time), p.vy_at(i, time), d.r, p.mass(i)}) {
      std::fputc(',', out);
      put(out, v);
    }
    if (!p.omega.empty())
      for (T v : {p.omega[i], p.inertia[i]}) {
        std::fputc(',', out);
        put(out, v);
      }
    std::fputc('\n', out);
  }
}

template <class T>
Status write_state_csv_file(const std::string& path, const Particles<T>& p, T time,
                            const std::vector<std::string>& species_names) {
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) return Error{"cannot write '" + path + "': " + std::strerror(errno)};
  write_state_csv(out, p, time, species_names);
  const bool failed = std::ferror(out) != 0;
  if (std::fclose(out) != 0 || failed) return Error{"error while writing '" + path + "': " + std::strerror(errno)};
  return Ok{};
}

template void write_state_csv<float>(std::FILE*, const Particles<float>&, float, const std::vector<std::string>&);
template void write_state_csv<double>(std::FILE*, const Particles<double>&, double, const std::vector<std::string>&);
template void write_state_csv<long double>(std::FILE*, const Particles<long double>&, long double,
                                           const std::vector<std::string>&);
template Status write_state_csv_file<float>(const std::string&, const Particles<float>&, float,
                                            const std::vector<std::string>&);
template Status write_state_csv_file<double>(const std::string&, const Particles<double>&, double,
                                             const std::vector<std::string>&);
template Status write_state_csv_file<long double>(const std::string&, const Particles<long double>&, long double,
                                                  const std::vector<std::string>&);
#if EDE_HAVE_FLOAT128
template void write_state_csv<__float128>(std::FILE*, const Particles<__float128>&, __float128,
                                          const std::vector<std::string>&);
template Status write_state_csv_file<__float128>(const std::string&, const Particles<__float128>&, __float128,
                                                 const std::vector<std::string>&);
#endif

}  // namespace ede
