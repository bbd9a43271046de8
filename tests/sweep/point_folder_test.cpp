// What a point's folder says on a re-run: fresh, resumable, done, or a run of
// another configuration (refused, naming the folder and the key).
#include "sweep/point_folder.hpp"

#include <gtest/gtest.h>

#include "io/io_test_files.hpp"
#include "sweep/tiny_sweep.hpp"

namespace dilatant::sweep::point_folder_test {
namespace {

TEST(PointFolder, TellsFreshResumableAndDonePointsApart) {
  test::TempDir dir;
  const SweepPlan plan = parse_sweep(test::kTinyGrid, "s.toml", ".", {});
  const SweepPoint& p = plan.points[1];
  const auto folder = dir.path() / p.folder;
  EXPECT_EQ(inspect_point_folder(p, folder), PointState::Fresh);  // no folder
  dir.write(p.folder + "/checkpoint.bin", "x");
  EXPECT_EQ(inspect_point_folder(p, folder), PointState::Fresh);  // no config.toml: not ours
  // The comment lines (which name the sweep file) do not count.
  dir.write(p.folder + "/config.toml", "# from elsewhere\n" + resolved_toml(p.config));
  EXPECT_EQ(inspect_point_folder(p, folder), PointState::Resumable);
  dir.write(p.folder + "/summary.json", "{}");
  EXPECT_EQ(inspect_point_folder(p, folder), PointState::Done);
  // Killed after writing its config.toml, before its first checkpoint: it
  // starts again from the beginning.
  const SweepPoint& q = plan.points[0];
  dir.write(q.folder + "/config.toml", resolved_toml(q.config));
  EXPECT_EQ(inspect_point_folder(q, dir.path() / q.folder), PointState::Fresh);
}

TEST(PointFolder, ARunOfAnotherConfigurationIsRefusedNamingTheKey) {
  test::TempDir dir;
  const SweepPlan before = parse_sweep(test::kTinyGrid, "s.toml", ".", {});
  const SweepPlan after = parse_sweep(test::kTinyGrid, "s.toml", ".", {"run.strain=0.4"});
  const auto folder = dir.path() / before.points[2].folder;
  dir.write(before.points[2].folder + "/config.toml", resolved_toml(before.points[2].config));
  dir.write(before.points[2].folder + "/summary.json", "{}");
  const std::string message =
      test::input_error_message([&] { inspect_point_folder(after.points[2], folder); });
  EXPECT_NE(message.find(folder.string() + ": holds a run of another configuration"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("run.strain = 0.3 there, 0.4 in this sweep"), std::string::npos)
      << message;
}

}  // namespace
}  // namespace dilatant::sweep::point_folder_test
