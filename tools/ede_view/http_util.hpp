// What every route shares: errors as JSON with a 4xx status, numbers read from query parameters with a
// message naming the parameter, and the one check that keeps requests inside the folders ede-view was
// given (--logs, --scenes).
//
// A requested file is named relative to one of those folders; it is made absolute, canonicalised
// (symlinks and ".." resolved by the file system, not by string rules) and accepted only if the result
// still lies under that folder's own canonical path. Rejected: filtering ".." out of names (misses
// symlinks, encodings and the many spellings of a path) and serving by absolute path.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <httplib.h>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frame.hpp"

namespace ede::view {

// {"error": message} with the status (400, 403, 404, 409, 413, ...).
void send_error(httplib::Response& res, int status, const std::string& message);
void send_json(httplib::Response& res, const std::string& json);

// A query parameter as a finite double; nothing and an error sent when missing (unless `fallback`) or bad.
std::optional<double> number_param(const httplib::Request& req, httplib::Response& res, const std::string& name,
                                   std::optional<double> fallback = std::nullopt);

// A frame's packing from ?max= (default `default_max`), ?exact= and ?colour=; nothing and a 400 sent when bad.
std::optional<FrameRequest> frame_request_param(const httplib::Request& req, httplib::Response& res,
                                                std::size_t default_max);
// The bytes of frames being sent: a frame is held until its page has read it (or the write timed out), so
// pages that ask and do not read would otherwise hold as many frames as there are workers. Above the limit
// (ede-view --frame-memory) a frame is refused with 503 and the page asks again later. A frame shared by
// several answers (a live run's) is counted once per answer: the bound is conservative.
struct FrameBudget {
  std::uint64_t limit = 0;
  std::atomic<std::uint64_t> used{0};
};
// A packed frame as the response's body, sent from the shared buffer (not copied: frames are megabytes),
// counted in `budget` until the answer is done; a 503 naming the limit when it would pass it (a frame alone
// larger than the whole budget is still sent when nothing else is in flight).
void send_frame(httplib::Response& res, std::shared_ptr<const std::string> frame, FrameBudget& budget);

// A folder ede-view may read from, by its canonical path.
struct Root {
  std::filesystem::path canonical;
};

// `name` ("sub/run.ede", relative to one of the roots, or prefixed by the root's index as "0:sub/run.ede")
// as a canonical path inside a root with the given extension, or an error message (and the status to send)
// naming what is wrong.
struct Resolved {
  std::filesystem::path path;
  int status = 200;
  std::string error;
};
Resolved resolve_under(const std::vector<Root>& roots, const std::string& name, const std::string& extension);

// Files with this extension under the roots (at most `limit`, depth at most 4), as names resolve_under takes.
std::vector<std::string> list_files(const std::vector<Root>& roots, const std::string& extension,
                                    std::size_t limit = 500);

}  // namespace ede::view
