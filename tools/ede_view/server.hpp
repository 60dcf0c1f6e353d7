// The ede-view server: cpp-httplib with the page's files, the log and live-run routes, and the limits that
// make it safe by default (listen on 127.0.0.1; requests only for files under the given folders; bodies
// over 64 KiB and URIs over 8 KiB refused; a Host header naming another machine refused while bound to a
// loopback address, against DNS rebinding; a port in use is an error, never shared (no SO_REUSEPORT);
// every error a JSON {"error": ...} with a 4xx status).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "http_util.hpp"

namespace ede::view {

struct ServerOptions {
  std::string host = "127.0.0.1";
  int port = 8080;
  std::vector<Root> log_roots, scene_roots;
  std::filesystem::path out_dir;
  std::uint64_t max_live_disks = 2000000;
  std::uint64_t frame_memory = 256ull << 20;  // bytes of frames in flight (FrameBudget)
};

class Server {
 public:
  explicit Server(const ServerOptions& options);
  ~Server();
  int bind();    // the port bound, or -1
  bool serve();  // until stop(); false if it could not serve
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace ede::view
