// Placeholder until ede-render is written.
#include <cstdio>
int main() {
  std::fprintf(stderr, "ede-render: not available yet\n");
  return 1;
}
