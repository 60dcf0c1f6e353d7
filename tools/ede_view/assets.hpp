// The page's files (tools/ede_view/web/), compiled into the binary by embed_assets.cmake: the server looks
// a request's path up in this table and never touches the disk for them.
// Rejected: serving web/ from the install tree (a second path to configure, and one more place a request
// could reach files).
#pragma once

#include <string_view>
#include <vector>

namespace ede::view {

struct Asset {
  const char* path;          // "/index.html"
  const char* content_type;  // "text/html; charset=utf-8"
  std::string_view body;
};

const std::vector<Asset>& assets();

}  // namespace ede::view
