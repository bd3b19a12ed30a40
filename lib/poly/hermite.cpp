#include "poly/hermite.h"

namespace pccd::poly {

int hankel_signature(const std::vector<int> &d) {
  // r = index of the last nonzero minor; the sequence is 1, D_1, ..., D_r.
  size_t r = d.size();
  while (r > 0 && d[r - 1] == 0) --r;
  std::vector<int> seq(r + 1);
  seq[0] = 1;
  for (size_t i = 1; i <= r; ++i) seq[i] = d[i - 1];
  // Frobenius rule for each run of zeros that follows a nonzero entry seq[h].
  for (size_t i = 1; i <= r; ++i) {
    if (seq[i] != 0) continue;
    size_t h = i - 1;  // seq[h] != 0: runs are filled left to right
    for (size_t j = 1; h + j <= r && d[h + j - 1] == 0; ++j) {
      long e = static_cast<long>(j) * static_cast<long>(j - 1) / 2;
      seq[h + j] = (e % 2 == 0) ? seq[h] : -seq[h];
    }
  }
  int sig = 0;
  for (size_t i = 0; i < r; ++i) sig += (seq[i] == seq[i + 1]) ? 1 : -1;
  return sig;
}

}  // namespace pccd::poly
