// Reading a CSV state; see setup_from_csv.hpp.
#include "setup/setup_from_csv.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_map>

namespace ede {

namespace {

constexpr std::string_view kHeader = "id,species,x,y,vx,vy,radius,mass";
// A state of rough (rotating) disks carries two more columns (ede/state.hpp).
constexpr std::string_view kRoughHeader = "id,species,x,y,vx,vy,radius,mass,omega,inertia";
constexpr const char* kColumns[] = {"id", "species", "x", "y", "vx", "vy", "radius", "mass", "omega", "inertia"};

std::string shown(std::string_view v) {
  std::string s(v.substr(0, 40));
  for (char& c : s)
    if (static_cast<unsigned char>(c) < 0x20) c = '?';
  return "'" + s + (v.size() > 40 ? "...'" : "'");
}

}  // namespace

Result<InitialState> parse_state_csv(const std::string& text, const std::string& name) {
  InitialState st;
  std::unordered_map<std::string, std::int32_t> species_index;
  std::size_t line_no = 0, pos = 0, fields = 8;
  const auto fail = [&](const std::string& what, const std::string& fix) {
    return Error{name + ":" + std::to_string(line_no) + ": error: " + what + ". Fix: " + fix + "."};
  };
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line_no == 1) {
      if (line != kHeader && line != kRoughHeader)
        return fail("the first line is " + shown(line) + ", not the header " + std::string(kHeader) + " (or, for rough disks, " +
                        std::string(kRoughHeader) + ")",
                    "start the file with that header (ede-replay state --at T -o FILE.csv writes this format)");
      fields = line == kHeader ? 8 : 10;
      continue;
    }
    if (line.empty()) continue;
    std::string_view field[10];
    std::size_t n = 0, from = 0;
    for (;;) {
      const std::size_t comma = line.find(',', from);
      if (n < 10) field[n] = line.substr(from, comma == std::string_view::npos ? std::string_view::npos : comma - from);
      ++n;
      if (comma == std::string_view::npos) break;
      from = comma + 1;
    }
    if (n != fields)
      return fail("the row has " + std::to_string(n) + " fields, not " + std::to_string(fields) + " (" +
                      std::string(fields == 8 ? kHeader : kRoughHeader) + ")",
                  "write one disk per line with all the header's fields");
    std::uint64_t id = 0;
    const auto [id_end, id_ec] = std::from_chars(field[0].data(), field[0].data() + field[0].size(), id);
    if (id_ec != std::errc() || id_end != field[0].data() + field[0].size() || id != st.size())
      return fail("the id is " + shown(field[0]) + ", not " + std::to_string(st.size()) + " (ids count 0, 1, 2, ... in order)",
                  "number the rows from 0 without gaps");
    if (field[1].empty()) return fail("the species name is empty", "give every disk its species' name");
    double v[8];
    for (int k = 0; k < int(fields) - 2; ++k) {
      const std::string_view f = field[k + 2];
      const auto [e, ec] = std::from_chars(f.data(), f.data() + f.size(), v[k]);
      if (ec != std::errc() || e != f.data() + f.size() || !std::isfinite(v[k]))
        return fail("column '" + std::string(kColumns[k + 2]) + "' is " + shown(f) + ", not a finite number",
                    "write a number such as 0.25 or 1e-3");
    }
    if (!(v[4] > 0)) return fail("the radius is not positive", "give every disk a radius > 0");
    if (!(v[5] > 0)) return fail("the mass is not positive", "give every disk a mass > 0");
    if (fields == 10 && !(v[7] > 0)) return fail("the moment of inertia is not positive", "give every disk an inertia > 0");
    const std::string sp(field[1]);
    auto it = species_index.find(sp);
    if (it == species_index.end()) {
      it = species_index.emplace(sp, std::int32_t(st.species_names.size())).first;
      st.species_names.push_back(sp);
    }
    st.add(v[0], v[1], v[2], v[3], v[4], v[5], it->second);
    if (fields == 10) st.omega.push_back(v[6]), st.inertia.push_back(v[7]);
  }
  if (line_no == 0) return Error{name + ": error: the file is empty. Fix: give a CSV state (header " + std::string(kHeader) + ")."};
  if (st.size() == 0)
    return Error{name + ": error: the file has a header but no disks. Fix: add one row per disk."};
  return st;
}

Result<InitialState> read_state_csv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return Error{path + ": error: cannot read the CSV state. Fix: check the path (relative paths are relative to the "
                        "scene file's folder).",
                 ErrorKind::Io};
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) return Error{path + ": error: cannot read the CSV state. Fix: check the file.", ErrorKind::Io};
  return parse_state_csv(text.str(), path);
}

}  // namespace ede
