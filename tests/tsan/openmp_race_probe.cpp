// scripts/tsan.sh's check of itself: built with the same ThreadSanitizer and
// OpenMP (LLVM libomp + Archer) set-up as build-tsan/, this must report the
// race of the first loop (line 12) and nothing on the second region, whose two
// loops (lines 18, 21) a barrier orders. A set-up that missed the race would pass racy code;
// one that reported the barrier would drown real reports in false ones.
#include <cstdio>

int main() {
  int sum = 0;
#pragma omp parallel for num_threads(2) schedule(static)
  for (int i = 0; i < 1000; ++i) {
    sum += i;  // the race: every thread adds to one int
  }
  double a[1000] = {}, b[1000] = {};
#pragma omp parallel num_threads(2)
  {
#pragma omp for schedule(static) nowait
    for (int i = 0; i < 1000; ++i) a[i] = i;
#pragma omp barrier
#pragma omp for schedule(static)
    for (int i = 0; i < 1000; ++i) b[i] = a[999 - i];  // the other thread's half of a
  }
  std::printf("%d %g\n", sum, b[3]);
  return 0;
}
