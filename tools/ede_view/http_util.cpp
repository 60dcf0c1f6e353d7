// Errors, parameters and the path check; see http_util.hpp.
#include "http_util.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace ede::view {

namespace fs = std::filesystem;

void send_error(httplib::Response& res, int status, const std::string& message) {
  res.status = status;
  res.set_content(nlohmann::json{{"error", message}}.dump(), "application/json");
}

void send_json(httplib::Response& res, const std::string& json) {
  res.set_header("Cache-Control", "no-store");
  res.set_content(json, "application/json");
}

std::optional<double> number_param(const httplib::Request& req, httplib::Response& res, const std::string& name,
                                   std::optional<double> fallback) {
  if (!req.has_param(name)) {
    if (fallback) return fallback;
    send_error(res, 400, "missing parameter '" + name + "'");
    return std::nullopt;
  }
  const std::string text = req.get_param_value(name);
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(v)) {
    send_error(res, 400, "parameter '" + name + "' must be a finite number, not '" + text.substr(0, 40) + "'");
    return std::nullopt;
  }
  return v;
}

std::optional<FrameRequest> frame_request_param(const httplib::Request& req, httplib::Response& res,
                                                std::size_t default_max) {
  const auto max = number_param(req, res, "max", double(default_max));
  if (!max) return std::nullopt;
  auto r = frame_request(*max >= 1 && *max < 4e9 ? std::size_t(*max) : default_max, req.get_param_value("exact"),
                         req.get_param_value("colour"));
  if (!r) {
    send_error(res, 400, r.error().message);
    return std::nullopt;
  }
  return r.value();
}

void send_frame(httplib::Response& res, std::shared_ptr<const std::string> frame, FrameBudget& budget) {
  const std::size_t size = frame->size();
  const std::uint64_t before = budget.used.fetch_add(size);
  if (before > 0 && before + size > budget.limit) {
    budget.used -= size;
    return send_error(res, 503, "busy: " + std::to_string((before + (1u << 20) - 1) >> 20) +
                                    " MiB of frames are being sent to other pages (ede-view --frame-memory " +
                                    std::to_string(budget.limit >> 20) + "); ask again");
  }
  // Released when httplib drops the provider: the answer sent, or its connection closed or timed out.
  std::shared_ptr<void> counted(nullptr, [&budget, size](void*) { budget.used -= size; });
  res.set_header("Cache-Control", "no-store");
  res.set_content_provider(size, "application/octet-stream",
                           [frame = std::move(frame), counted = std::move(counted)](
                               std::size_t offset, std::size_t length, httplib::DataSink& sink) {
                             return sink.write(frame->data() + offset, length);
                           });
}

namespace {

bool inside(const fs::path& path, const fs::path& root) {
  auto r = root.begin(), p = path.begin();
  for (; r != root.end(); ++r, ++p)
    if (p == path.end() || *p != *r) return false;
  return true;
}

}  // namespace

Resolved resolve_under(const std::vector<Root>& roots, const std::string& name, const std::string& extension) {
  if (name.empty() || name.size() > 1024 || name.find('\0') != std::string::npos)
    return {{}, 400, "a file name of 1 to 1024 characters is needed"};
  std::size_t first = 0, last = roots.size();
  std::string rel = name;
  if (const auto colon = name.find(':'); colon != std::string::npos && colon > 0 && colon <= 3 &&
                                         name.find_first_not_of("0123456789") == colon) {
    first = std::stoul(name.substr(0, colon));
    last = first + 1;
    rel = name.substr(colon + 1);
    if (first >= roots.size()) return {{}, 404, "no folder number " + name.substr(0, colon) + " is served"};
  }
  if (fs::path(rel).is_absolute()) return {{}, 403, "'" + name + "': absolute paths are refused; name a file under a served folder"};
  for (std::size_t k = first; k < last; ++k) {
    std::error_code ec;
    const fs::path candidate = fs::weakly_canonical(roots[k].canonical / rel, ec);
    if (ec) continue;
    if (!inside(candidate, roots[k].canonical))
      return {{}, 403, "'" + name + "' is outside the folders ede-view serves"};
    if (candidate.extension() != extension) return {{}, 403, "'" + name + "': only " + extension + " files are served"};
    if (fs::is_regular_file(candidate, ec)) return {candidate, 200, ""};
  }
  return {{}, 404, "no file '" + name + "' under the folders ede-view serves"};
}

std::vector<std::string> list_files(const std::vector<Root>& roots, const std::string& extension, std::size_t limit) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < roots.size(); ++k) {
    std::error_code ec;
    fs::recursive_directory_iterator it(roots[k].canonical, fs::directory_options::skip_permission_denied, ec), end;
    for (; !ec && it != end && out.size() < limit; it.increment(ec)) {
      if (it.depth() >= 4) it.disable_recursion_pending();
      // Per entry its own error code: a broken or looping symlink skips that entry, not the rest.
      std::error_code entry_ec;
      if (!it->is_regular_file(entry_ec) || it->path().extension() != extension) continue;
      // A symlink that leads out of the folder is not listed (resolve_under would refuse it anyway).
      const fs::path target = fs::canonical(it->path(), entry_ec);
      if (entry_ec || !inside(target, roots[k].canonical)) continue;
      out.push_back(std::to_string(k) + ":" + fs::relative(it->path(), roots[k].canonical, entry_ec).generic_string());
    }
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace ede::view
