#pragma once
// 3-vectors are Eigen's fixed-size vectors: no heap, fully inlined, and a reader
// already knows their API.
#include <Eigen/Core>
#include <Eigen/Geometry>  // cross() is declared in Core but defined here

namespace dilatant {
using Vec3 = Eigen::Vector3d;
}
