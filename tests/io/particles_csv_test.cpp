#include "io/particles_csv.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "io/input_error.hpp"
#include "io/io_test_files.hpp"

namespace dilatant::particles_csv_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(ParticlesCsv, ReadsRequiredColumnsInAnyOrderWithDefaults) {
  test::TempDir dir;
  const auto file = dir.write("p.csv", "r, id ,x,y,z\n1.0,7,0,0,1.5\n\n  0.5,8,-1e-3,+2,3  \n");
  const auto p = read_particles_csv(file);
  ASSERT_EQ(p.size(), 2u);
  EXPECT_EQ(p[0].id, 7);
  EXPECT_EQ(p[0].position, Vec3(0.0, 0.0, 1.5));
  EXPECT_EQ(p[0].radius, 1.0);
  EXPECT_EQ(p[0].velocity, Vec3::Zero());
  EXPECT_EQ(p[0].angular_velocity, Vec3::Zero());
  EXPECT_FALSE(p[0].fixed);
  EXPECT_EQ(p[1].id, 8);
  EXPECT_EQ(p[1].position, Vec3(-1e-3, 2.0, 3.0));
  EXPECT_EQ(p[1].radius, 0.5);
}

TEST(ParticlesCsv, ReadsOptionalColumnsAndCrlf) {
  test::TempDir dir;
  const auto file = dir.write("p.csv",
                              "id,x,y,z,r,vx,vy,vz,wx,wy,wz,fixed\r\n"
                              "1,0,0,1,1,0.5,-0.5,2,1,2,3,1\r\n"
                              "2,3,0,1,1,0,0,0,0,0,0,false\r\n"
                              "3,6,0,1,1,0,0,0,0,0,0,TRUE\r\n");
  const auto p = read_particles_csv(file);
  ASSERT_EQ(p.size(), 3u);
  EXPECT_EQ(p[0].velocity, Vec3(0.5, -0.5, 2.0));
  EXPECT_EQ(p[0].angular_velocity, Vec3(1.0, 2.0, 3.0));
  EXPECT_TRUE(p[0].fixed);
  EXPECT_FALSE(p[1].fixed);
  EXPECT_TRUE(p[2].fixed);
}

TEST(ParticlesCsv, AcceptsAnySubsetOfOptionalColumns) {
  test::TempDir dir;
  const auto p = read_particles_csv(dir.write("p.csv", "id,x,y,z,r,vz,wy\n1,0,0,1,1,-2,4\n"));
  ASSERT_EQ(p.size(), 1u);
  EXPECT_EQ(p[0].velocity, Vec3(0.0, 0.0, -2.0));
  EXPECT_EQ(p[0].angular_velocity, Vec3(0.0, 4.0, 0.0));
}

// A bad file, and what its message must contain.
struct BadCsv {
  std::string name;
  std::string text;
  std::string expected;
};

class ParticlesCsvBadInput : public ::testing::TestWithParam<BadCsv> {};

TEST_P(ParticlesCsvBadInput, ThrowsOneLineNamingFileAndLine) {
  test::TempDir dir;
  const auto file = dir.write("particles.csv", GetParam().text);
  const auto message = test::input_error_message([&] { read_particles_csv(file); });
  EXPECT_THAT(message, HasSubstr("particles.csv"));
  EXPECT_THAT(message, HasSubstr(GetParam().expected));
  EXPECT_THAT(message, Not(HasSubstr("\n")));
}

INSTANTIATE_TEST_SUITE_P(
    ParticlesCsv, ParticlesCsvBadInput,
    ::testing::Values(
        BadCsv{"EmptyFile", "", "empty file"}, BadCsv{"OnlyBlankLines", "\n  \n\r\n", "empty file"},
        BadCsv{"NoParticles", "id,x,y,z,r\n\n", "no particles"},
        BadCsv{"MissingColumn", "id,x,y,z\n1,0,0,0\n", ":1: missing required column 'r'"},
        BadCsv{"UnknownColumn", "id,x,y,z,r,mass\n", ":1: unknown column 'mass'"},
        BadCsv{"DuplicateColumn", "id,x,y,z,r,x\n", ":1: duplicate column 'x'"},
        BadCsv{"EmptyColumnName", "id,x,,y,z,r\n", ":1: header has an empty column name"},
        BadCsv{"TooFewFields", "id,x,y,z,r\n1,0,0,0,1\n2,0,0,0\n",
               ":3: 4 fields, the header has 5"},
        BadCsv{"TooManyFields", "id,x,y,z,r\n1,0,0,0,1,\n", ":2: 6 fields, the header has 5"},
        BadCsv{"TextInNumber", "id,x,y,z,r\n\n\n1,0,0,0,abc\n",
               ":4: column 'r': 'abc' is not a number"},
        BadCsv{"TrailingGarbage", "id,x,y,z,r\n1,0,0,1.5m,1\n",
               "column 'z': '1.5m' is not a number"},
        BadCsv{"EmptyField", "id,x,y,z,r\n1,0, ,0,1\n", ":2: column 'y': empty field"},
        BadCsv{"NanNumber", "id,x,y,z,r\n1,nan,0,0,1\n", "column 'x': 'nan' is not finite"},
        BadCsv{"InfNumber", "id,x,y,z,r,vx\n1,0,0,0,1,-inf\n", "column 'vx': '-inf' is not finite"},
        BadCsv{"NonIntegerId", "id,x,y,z,r\n1.5,0,0,0,1\n", "column 'id': '1.5' is not an integer"},
        BadCsv{"ZeroRadius", "id,x,y,z,r\n1,0,0,0,0\n", ":2: column 'r': radius must be > 0"},
        BadCsv{"NegativeRadius", "id,x,y,z,r\n1,0,0,0,-1\n", "radius must be > 0, got -1"},
        BadCsv{"DuplicateId", "id,x,y,z,r\n4,0,0,0,1\n5,3,0,0,1\n4,6,0,0,1\n",
               ":4: duplicate id 4 (first on line 2)"},
        BadCsv{"BadFixed", "id,x,y,z,r,fixed\n1,0,0,0,1,yes\n",
               "column 'fixed': 'yes' is not 0, 1, true or false"}),
    [](const ::testing::TestParamInfo<BadCsv>& p) { return p.param.name; });

TEST(ParticlesCsv, MissingFileIsAnInputError) {
  test::TempDir dir;
  EXPECT_THAT(test::input_error_message([&] { read_particles_csv(dir.path() / "none.csv"); }),
              HasSubstr("none.csv: cannot read the particle file (no such file)"));
  EXPECT_THAT(test::input_error_message([&] { read_particles_csv(dir.path()); }),
              HasSubstr("not a readable file"));
}

}  // namespace
}  // namespace dilatant::particles_csv_test
