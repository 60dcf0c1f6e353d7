// Enskog's self-diffusion coefficient and Henderson's contact value of hard disks (transport.hpp; the
// formulas and their checks in docs/analysis.md). Rejected: inlining them in the header, which would put
// the formulas' sources out of the analysis room's files.
#include <cmath>

#include "ede/transport.hpp"

namespace ede {

double enskog_diffusion(double n, double sigma, double g_contact, double kT, double mass) {
  return 1 / (2 * n * sigma * g_contact) * std::sqrt(kT / (M_PI * mass));
}

double henderson_contact(double phi) { return (1 - 7 * phi / 16) / ((1 - phi) * (1 - phi)); }

}  // namespace ede
