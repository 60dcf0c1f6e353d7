// Server: the routes and limits of server.hpp on a cpp-httplib Server.
#include "server.hpp"

#include <httplib.h>
#include <sys/socket.h>

#include <nlohmann/json.hpp>

#include "assets.hpp"
#include "live_routes.hpp"
#include "log_routes.hpp"

namespace ede::view {

constexpr std::size_t kMaxBody = 64 * 1024;
// Connections are served one per worker thread (cpp-httplib blocks on each), so an idle keep-alive socket,
// a request arriving byte by byte or a page that does not read its frame holds a worker until its timeout.
// Many workers (idle threads cost a stack's address space, not memory) and short timeouts keep a page
// answered while dozens of others do that (tests/tools/view/test_view_abuse.py). Rejected: httplib's
// default of max(8, cores - 1) workers and 5 s timeouts, with which eight idle browser sockets made every
// other page wait seconds.
constexpr std::size_t kWorkers = 128;
constexpr time_t kKeepAliveSeconds = 2;  // an idle connection is closed after this
constexpr time_t kReadSeconds = 2;       // a request that stops arriving for this long is dropped
constexpr time_t kWriteSeconds = 5;      // an answer the page stops reading for this long is dropped

struct Server::Impl {
  ServerOptions options;
  FrameBudget budget;  // before http: answers still in flight release into it
  httplib::Server http;
  LiveRuns runs;
  explicit Impl(const ServerOptions& o) : options(o), runs(o.out_dir, o.max_live_disks) {
    budget.limit = o.frame_memory;
  }
};

namespace {

bool loopback(const std::string& host) { return host == "127.0.0.1" || host == "localhost" || host == "::1"; }

// While bound to loopback, a request must name this machine in its Host header (a page on another site
// that resolves its own name to 127.0.0.1 would name that site).
bool host_allowed(const httplib::Request& req) {
  std::string host = req.get_header_value("Host");
  if (host.empty()) return true;
  if (host.front() == '[') host = host.substr(0, host.find(']') + 1);
  else host = host.substr(0, host.find(':'));
  return host == "127.0.0.1" || host == "localhost" || host == "[::1]";
}

void add_assets(httplib::Server& http) {
  http.Get("/", [](const httplib::Request&, httplib::Response& res) {
    for (const Asset& a : assets())
      if (std::string_view(a.path) == "/index.html") return res.set_content(a.body.data(), a.body.size(), a.content_type);
    send_error(res, 404, "the page is missing from this build");
  });
  for (const Asset& a : assets())
    http.Get(a.path, [&a](const httplib::Request&, httplib::Response& res) {
      res.set_content(a.body.data(), a.body.size(), a.content_type);
    });
}

}  // namespace

Server::Server(const ServerOptions& options) : impl_(std::make_unique<Impl>(options)) {
  httplib::Server& http = impl_->http;
  http.set_payload_max_length(kMaxBody);
  http.new_task_queue = [] { return new httplib::ThreadPool(kWorkers); };
  http.set_keep_alive_timeout(kKeepAliveSeconds);
  http.set_read_timeout(kReadSeconds, 0);
  http.set_write_timeout(kWriteSeconds, 0);
  http.set_tcp_nodelay(true);
  // SO_REUSEADDR only: httplib's default adds SO_REUSEPORT, with which a second server (or another local
  // program) could bind the same port and silently take half of the requests.
  http.set_socket_options([](socket_t sock) {
    int yes = 1;
    ::setsockopt(sock, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
  });  // frames are written in pieces: Nagle would hold the last one back
  http.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"X-Frame-Options", "DENY"}});
  const bool check_host = loopback(options.host);
  http.set_pre_routing_handler([check_host](const httplib::Request& req, httplib::Response& res) {
    if (check_host && !host_allowed(req)) {
      send_error(res, 403, "this server answers only requests for localhost (Host: " +
                               req.get_header_value("Host").substr(0, 100) + ")");
      return httplib::Server::HandlerResponse::Handled;
    }
    return httplib::Server::HandlerResponse::Unhandled;
  });
  add_assets(http);
  add_log_routes(http, options.log_roots, impl_->budget);
  add_live_routes(http, options.scene_roots, impl_->runs, impl_->budget);
  // Statuses httplib sets itself (no route, 413 payload too large, 414 URI too long, 400 malformed)
  // get a JSON body too.
  http.set_error_handler([](const httplib::Request& req, httplib::Response& res) {
    if (!res.body.empty()) return;
    std::string message = "error " + std::to_string(res.status);
    if (res.status == 404) message = "no such page or API: " + req.path.substr(0, 200);
    if (res.status == 413) message = "request body too large (at most 64 KiB)";
    if (res.status == 414) message = "request URI too long (at most 8 KiB)";
    if (res.status == 405) message = "method not allowed";
    if (res.status == 400) message = "bad request (a POST needs a Content-Length header, e.g. an empty body)";
    res.set_content(nlohmann::json{{"error", message}}.dump(), "application/json");
  });
  http.set_exception_handler([](const httplib::Request&, httplib::Response& res, std::exception_ptr ep) {
    std::string what = "internal error";
    try {
      std::rethrow_exception(ep);
    } catch (const std::exception& e) {
      what += std::string(": ") + e.what();
    } catch (...) {
    }
    send_error(res, 500, what);
  });
}

Server::~Server() = default;

int Server::bind() {
  if (impl_->options.port == 0) return impl_->http.bind_to_any_port(impl_->options.host);
  return impl_->http.bind_to_port(impl_->options.host, impl_->options.port) ? impl_->options.port : -1;
}

bool Server::serve() { return impl_->http.listen_after_bind(); }

void Server::stop() { impl_->http.stop(); }

}  // namespace ede::view
