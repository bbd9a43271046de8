#pragma once
// 3-vectors are Eigen's fixed-size vectors: no heap, fully inlined, and a reader
// already knows their API.
#include <Eigen/Core>

namespace dilatant {
using Vec3 = Eigen::Vector3d;
}
