#pragma once
// The smallest useful shear-cell sweep for tests: a 6 x 5 x 7 R cell (29 mobile
// spheres) sheared to strain 0.3, a few hundredths of a second per point in
// Release, a second or so with the sanitizers.
#include <string>

namespace dilatant::test {

// A run configuration without the swept keys; append lists or [[points]].
inline const std::string kTinyCell = R"(# a tiny sweep for tests
[cell]
size = [6.0, 5.0, 7.0]
phi = 0.58

[solver]
tolerance = 1e-2

[run]
strain = 0.3
transient_strain = 0.1
snapshot_interval = 0.0
)";

// kTinyCell with mu0 and lambda swept: the 2 x 2 grid of the CI test.
inline const std::string kTinyGrid = kTinyCell + R"(
[friction]
mu0 = [0.1, 0.4]

[fluid]
lambda = [3.0, 30.0]
)";

}  // namespace dilatant::test
