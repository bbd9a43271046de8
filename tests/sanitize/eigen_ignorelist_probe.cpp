// The sanitizer tree leaves UBSan's alignment, null and object-size checks out
// of Eigen's headers (cmake/ubsan-ignorelist.txt). This probe shows, one fault
// per case, that what those checks guarded is still reported: scripts/test.sh
// builds it with the tree's flags and expects a report from every case.
//   eigen_ignorelist_probe CASE   (1-4; a report and a non-zero exit expected)
#include <Eigen/Core>
#include <cstdlib>
#include <vector>

using Vec3 = Eigen::Vector3d;

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const int fault = std::atoi(argv[1]);
  std::vector<Vec3> v(3, Vec3(1, 2, 3));
  Vec3* volatile null_vec = nullptr;
  alignas(16) char buffer[64] = {};
  switch (fault) {
    case 1:  // member call on a null vector: UBSan null, at our call site
      return static_cast<int>(null_vec->norm());
    case 2:  // one vector past the end of the array: ASan heap-buffer-overflow
      v.data()[3] += Vec3(1, 1, 1);
      return static_cast<int>(v[0](0));
    case 3: {  // a vector at a misaligned address: UBSan alignment, at our call site
      const Vec3* misaligned = reinterpret_cast<const Vec3*>(buffer + 1);
      return static_cast<int>(misaligned->squaredNorm());
    }
    case 4:  // a coefficient out of range: Eigen's own assertion (no NDEBUG in this tree)
      return static_cast<int>(v[1](3));
    default:
      return 2;
  }
}
