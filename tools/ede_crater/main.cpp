// Placeholder until ede-crater is written.
#include <cstdio>
int main() {
  std::fprintf(stderr, "ede-crater: not available yet\n");
  return 1;
}
