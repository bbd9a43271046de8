#include "detection/contact_detector.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "geometry/reduced_radius.hpp"

namespace dilatant {

namespace {
// A non-periodic axis spanned by far-flung particles must not explode the grid.
constexpr int kMaxCellsPerAxis = 512;
}  // namespace

void finish_contact(const Bodies& b, Contact& c) {
  const double im_i = b.inv_mass[c.i];
  const double ii_i = b.inv_inertia[c.i];
  c.arm_i = b.radius[c.i];
  double w_n = im_i;
  double w_t = im_i + ii_i * c.arm_i * c.arm_i;
  if (!c.with_plane()) {
    const double im_j = b.inv_mass[c.other];
    const double ii_j = b.inv_inertia[c.other];
    c.arm_j = b.radius[c.other];
    w_n += im_j;
    w_t += im_j + ii_j * c.arm_j * c.arm_j;
    c.reduced_radius = reduced_radius(c.arm_i, c.arm_j);
  } else {
    c.arm_j = 0.0;
    c.reduced_radius = reduced_radius_on_plane(c.arm_i);
  }
  c.w_n = w_n;
  c.w_t = w_t;
}

void ContactDetector::build_cells(const World& world, double cell_size) {
  const Bodies& b = world.bodies;
  const std::size_t n = b.size();
  Vec3 lo = Vec3::Constant(0.0), hi = Vec3::Constant(0.0);
  if (n > 0) {
    lo = hi = world.box.wrap(b.position[0]);
    for (std::size_t i = 1; i < n; ++i) {
      const Vec3 x = world.box.wrap(b.position[i]);
      lo = lo.cwiseMin(x);
      hi = hi.cwiseMax(x);
    }
  }
  for (int k = 0; k < 3; ++k) {
    if (world.box.periodic[k]) {
      origin_[k] = 0.0;
      n_cells_[k] = std::max(1, static_cast<int>(world.box.length[k] / cell_size));
      cell_edge_[k] = world.box.length[k] / n_cells_[k];
    } else {
      origin_[k] = lo[k];
      const double extent = hi[k] - lo[k];
      n_cells_[k] = std::clamp(static_cast<int>(extent / cell_size) + 1, 1, kMaxCellsPerAxis);
      cell_edge_[k] = std::max(cell_size, extent / n_cells_[k] * (1.0 + 1e-12));
    }
  }
  const int total = n_cells_[0] * n_cells_[1] * n_cells_[2];
  cell_start_.assign(static_cast<std::size_t>(total) + 1, 0);
  body_cell_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 x = world.box.wrap(b.position[i]);
    std::array<int, 3> c{};
    for (int k = 0; k < 3; ++k) {
      c[k] = std::clamp(static_cast<int>((x[k] - origin_[k]) / cell_edge_[k]), 0, n_cells_[k] - 1);
    }
    body_cell_[i] = (c[2] * n_cells_[1] + c[1]) * n_cells_[0] + c[0];
    ++cell_start_[body_cell_[i] + 1];
  }
  for (int c = 0; c < total; ++c) cell_start_[c + 1] += cell_start_[c];
  cell_body_.resize(n);
  std::vector<std::int32_t> fill(cell_start_.begin(), cell_start_.end() - 1);
  for (std::size_t i = 0; i < n; ++i)
    cell_body_[fill[body_cell_[i]]++] = static_cast<std::int32_t>(i);
}

void ContactDetector::add_pair_contacts(const World& world, double margin, std::size_t i,
                                        std::vector<Contact>& contacts) const {
  const Bodies& b = world.bodies;
  // 9 cells in each of the three z rows, and 12 in a row across a Lees–Edwards
  // boundary: at most 9 + 12 + 12.
  std::array<int, 33> neighbours{};
  {
    const int ci = body_cell_[i];
    const int cx = ci % n_cells_[0], cy = (ci / n_cells_[0]) % n_cells_[1],
              cz = ci / (n_cells_[0] * n_cells_[1]);
    const bool sheared = world.box.lees_edwards && world.box.periodic[2];
    // Neighbour cells, each once even when a periodic axis has fewer than 3 cells.
    int count = 0;
    for (int dz = -1; dz <= 1; ++dz) {
      // Across z under Lees–Edwards the copy above is displaced by +offset, so
      // its bodies near x_i came from x_i - offset: the x range of cells moves
      // by -offset/edge (+offset/edge below) and, not falling on a cell
      // border, spans four cells instead of three.
      const int z = cz + dz;
      const bool across = sheared && (z < 0 || z >= n_cells_[2]);
      int x_first = cx - 1, x_last = cx + 1;
      if (across) {
        const double shift = (z < 0 ? 1.0 : -1.0) * world.box.shear_offset / cell_edge_[0];
        x_first = static_cast<int>(std::floor(cx - 1 + shift));
        x_last = x_first + 3;
      }
      for (int dy = -1; dy <= 1; ++dy) {
        for (int x = x_first; x <= x_last; ++x) {
          std::array<int, 3> c = {x, cy + dy, z};
          bool inside = true;
          for (int k = 0; k < 3; ++k) {
            if (c[k] >= 0 && c[k] < n_cells_[k]) continue;
            if (!world.box.periodic[k]) {
              inside = false;
              break;
            }
            c[k] = ((c[k] % n_cells_[k]) + n_cells_[k]) % n_cells_[k];
          }
          if (inside) neighbours[count++] = (c[2] * n_cells_[1] + c[1]) * n_cells_[0] + c[0];
        }
      }
    }
    std::sort(neighbours.begin(), neighbours.begin() + count);
    count = static_cast<int>(std::unique(neighbours.begin(), neighbours.begin() + count) -
                             neighbours.begin());
    const std::size_t first = contacts.size();
    for (int q = 0; q < count; ++q) {
      const int cell = neighbours[q];
      for (int s = cell_start_[cell]; s < cell_start_[cell + 1]; ++s) {
        const auto j = static_cast<std::size_t>(cell_body_[s]);
        if (j <= i || (b.is_fixed(i) && b.is_fixed(j))) continue;
        const PeriodicBox::Image image = world.box.nearest_image(b.position[i], b.position[j]);
        const Vec3& d = image.d;
        const double dist = d.norm();
        const double gap = dist - b.radius[i] - b.radius[j];
        if (gap > margin) continue;
        Contact c;
        c.i = static_cast<std::int32_t>(i);
        c.other = static_cast<std::int32_t>(j);
        c.normal = dist > 0.0 ? Vec3(d / dist) : Vec3::UnitZ();
        c.gap = gap;
        c.image_drift = sheared ? image.image * world.box.shear_velocity : 0.0;
        c.dilation_drift = world.box.dilation_rate * d[2];
        finish_contact(b, c);
        contacts.push_back(c);
      }
    }
    // i's partners in the order of j: blocks of consecutive i joined in order
    // then give the (i, j) order of the whole list without a global sort.
    std::sort(contacts.begin() + static_cast<std::ptrdiff_t>(first), contacts.end(),
              [](const Contact& a, const Contact& c) { return a.other < c.other; });
  }
}

void ContactDetector::detect(const World& world, double margin, std::vector<Contact>& contacts,
                             int threads) {
  contacts.clear();
  const Bodies& b = world.bodies;
  double r_max = 0.0;
  for (double r : b.radius) r_max = std::max(r_max, r);
  build_cells(world, 2.0 * r_max + margin);
  per_thread_.resize(static_cast<std::size_t>(std::max(1, threads)));
  for (auto& local : per_thread_) local.clear();  // OpenMP may start fewer threads
  const auto n = static_cast<std::int64_t>(b.size());
#pragma omp parallel num_threads(std::max(1, threads)) if (threads > 1)
  {
    std::vector<Contact>& local = per_thread_[static_cast<std::size_t>(omp_get_thread_num())];
    // Static schedule: thread t gets the t-th block of spheres, so joining the
    // blocks in thread order keeps the serial order.
#pragma omp for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      add_pair_contacts(world, margin, static_cast<std::size_t>(i), local);
    }
  }
  // Each thread's block is sorted by (i, j) and the blocks are in order of i.
  for (const auto& local : per_thread_) contacts.insert(contacts.end(), local.begin(), local.end());
  for (std::size_t k = 0; k < world.planes.size(); ++k) {
    const Plane& plane = world.planes[k];
    for (std::size_t i = 0; i < b.size(); ++i) {
      if (b.is_fixed(i)) continue;
      const double gap = plane.distance(b.position[i]) - b.radius[i];
      if (gap > margin) continue;
      Contact c;
      c.i = static_cast<std::int32_t>(i);
      c.other = -static_cast<std::int32_t>(k) - 1;
      c.normal = plane.normal;
      c.gap = gap;
      finish_contact(b, c);
      contacts.push_back(c);
    }
  }
}

}  // namespace dilatant
