// XYZ and CSV point files: the header's names in any order, the layouts by column count
// without one, comments and blank lines; every refusal names the file, line, column and
// field.
#include "core/io/files.hpp"
#include "core/pointcloud/cloud_files.hpp"
#include "core/pointcloud/point_text.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include <unistd.h>

namespace draught {
namespace {

std::string csv_error_of(std::string_view text, const std::string& name = "points.csv") {
  try {
    parse_point_text(text, name);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for this input";
  return "";
}

TEST(PointCloudText, HeaderInAnyOrderWithCommentsAndBlankLines) {
  const PointCloud c = parse_point_text(
      "# exported by a simulation\n"
      "\n"
      "Temperature, z, VX, y, vy, x, vz\n"
      "1500, 3, 0.5, 2, -1, 1, 0   # the first drop\n"
      "\r\n"
      "+1600,-3e-2,0,0.25,0,-1,2\r\n",
      "points.csv");
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c.position[0], glm::vec3(1, 2, 3));
  EXPECT_EQ(c.position[1], glm::vec3(-1, 0.25f, -0.03f));
  EXPECT_EQ(c.temperature, (std::vector<float>{1500, 1600}));
  EXPECT_EQ(c.velocity[0], glm::vec3(0.5f, -1, 0));
  EXPECT_EQ(c.velocity[1], glm::vec3(0, 0, 2));
  EXPECT_TRUE(c.radius.empty());
  EXPECT_TRUE(c.color.empty());
}

TEST(PointCloudText, ColumnCountsWithoutAHeader) {
  const PointCloud three = parse_point_text("1 2 3\n4 5 6\n", "a.xyz");
  EXPECT_EQ(three.position[1], glm::vec3(4, 5, 6));
  EXPECT_TRUE(three.radius.empty() && three.temperature.empty() && three.color.empty());
  const PointCloud four = parse_point_text("1 2 3 0.01\n", "a.xyz");
  EXPECT_EQ(four.radius, std::vector<float>{0.01f});
  const PointCloud five = parse_point_text("1\t2\t3\t0.01\t1800\n", "a.xyz");
  EXPECT_EQ(five.radius, std::vector<float>{0.01f});
  EXPECT_EQ(five.temperature, std::vector<float>{1800});
  const PointCloud six = parse_point_text("1,2,3,0.1,0.2,0.3\n", "a.csv");
  EXPECT_EQ(six.color.at(0), glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_TRUE(six.radius.empty());
  const PointCloud seven = parse_point_text("1 2 3 0.004 1 0.5 0\n", "a.xyz");
  EXPECT_EQ(seven.radius, std::vector<float>{0.004f});
  EXPECT_EQ(seven.color.at(0), glm::vec3(1, 0.5f, 0));
}

TEST(PointCloudText, AHeaderAloneIsAnEmptyCloud) {
  EXPECT_EQ(parse_point_text("x,y,z\n# nothing yet\n", "empty.csv").size(), 0u);
}

TEST(PointCloudText, ErrorsNameLineColumnAndField) {
  EXPECT_EQ(csv_error_of("x,y,z\n1,2,3\n\n# c\n1,2,3\n\n1,2,abc\n"), "points.csv: line 7, column 3 (z): expected a number, got \"abc\"");
  EXPECT_EQ(csv_error_of("1 2 3\n1 2 3 4\n", "a.xyz"), "a.xyz: line 2: expected 3 columns (as line 1 has), got more");
  EXPECT_EQ(csv_error_of("x y radius z\n1 2 0.1\n", "a.xyz"), "a.xyz: line 2: expected 4 columns (as the header on line 1 names), got 3");
  EXPECT_EQ(csv_error_of("1 2 nan\n"), "points.csv: line 1, column 3 (z): expected a finite coordinate in [-1e6, 1e6] m, got \"nan\"");
  EXPECT_EQ(csv_error_of("1 2 3\n-inf 2 3\n"), "points.csv: line 2, column 1 (x): expected a finite coordinate in [-1e6, 1e6] m, got \"-inf\"");
  EXPECT_EQ(csv_error_of("x,y,z,R,G,B\n0,0,0,-0.01,0,0\n"), "points.csv: line 2, column 4 (R): expected a linear colour channel in [0, 1], got \"-0.01\"");
  EXPECT_EQ(csv_error_of("0 0 0 -0.01\n"), "points.csv: line 1, column 4 (radius): expected a radius in [1e-9, 1e6] (the file's units), got \"-0.01\"");
  EXPECT_EQ(csv_error_of("0 0 0 0.01 -5\n"), "points.csv: line 1, column 5 (temperature): expected a temperature in [0, 10000] K, got \"-5\"");
  EXPECT_EQ(csv_error_of("0 0 0 0.01 1 1.5 0\n"), "points.csv: line 1, column 6 (g): expected a linear colour channel in [0, 1], got \"1.5\"");
  // Decimal numbers only: no hex, no trailing text; beyond double's range is infinite.
  EXPECT_EQ(csv_error_of("1 2 0x10\n"), "points.csv: line 1, column 3 (z): expected a number, got \"0x10\"");
  EXPECT_EQ(csv_error_of("1 2 3m\n"), "points.csv: line 1, column 3 (z): expected a number, got \"3m\"");
  EXPECT_EQ(csv_error_of("1 2 1e999\n"), "points.csv: line 1, column 3 (z): expected a finite coordinate in [-1e6, 1e6] m, got \"1e999\"");
  EXPECT_EQ(parse_point_text("-1.5e-3 +2 .5\n", "a.xyz").position.at(0), glm::vec3(-1.5e-3f, 2, 0.5f));
  EXPECT_EQ(csv_error_of("1,2,,3\n"), "points.csv: line 1, column 3 (z): expected a number, got \"\"");
  EXPECT_EQ(csv_error_of("1 2\n"),
            "points.csv: line 1: 2 columns without a header: expected 3 (x y z), 4 (x y z radius), 5 (x y z radius "
            "temperature), 6 (x y z r g b) or 7 (x y z radius r g b), or a first line naming the columns");
  EXPECT_EQ(csv_error_of("1 2 3 4 5 6 7 8\n"),
            "points.csv: line 1: 8 or more columns without a header: expected 3 (x y z), 4 (x y z radius), 5 (x y z "
            "radius temperature), 6 (x y z r g b) or 7 (x y z radius r g b), or a first line naming the columns");
}

TEST(PointCloudText, HeaderErrors) {
  EXPECT_EQ(csv_error_of("x,y,z,radus\n"),
            "points.csv: line 1, column 4: unknown column \"radus\" (did you mean 'radius'?): expected x, y, z, radius, "
            "temperature, r, g, b, vx, vy or vz (the first line names the columns when it is not a point)");
  EXPECT_EQ(csv_error_of("x,y\n"), "points.csv: line 1 (the header): no 'z': expected x, y and z");
  EXPECT_EQ(csv_error_of("x y z x\n"), "points.csv: line 1 (the header): 'x' is given twice");
  EXPECT_EQ(csv_error_of("x y z red g b\n"),
            "points.csv: line 1 (the header): the colour mixes spellings: expected one of r g b, red green blue or "
            "diffuse_red diffuse_green diffuse_blue");
  EXPECT_EQ(csv_error_of("x y z vx vy\n"), "points.csv: line 1 (the header): a velocity is given in part: expected also 'vz'");
}

TEST(PointCloudText, AtMostTheLimitOfPoints) {
  std::string rows;
  rows.reserve((kMaxCloudPoints + 1) * 6);
  for (std::size_t i = 0; i < kMaxCloudPoints; ++i) rows += "0 0 0\n";
  rows += "1 1 1\n";  // the points before it were read: the error is at the one over
  EXPECT_EQ(csv_error_of(rows, "big.xyz"), "big.xyz: line " + std::to_string(kMaxCloudPoints + 1) +
                                           ": more than 4194304 points: expected at most that many (the limit of a point cloud)");
}

TEST(PointCloudText, EmptyFiles) {
  const std::string expected =
      ": no points and no header: expected lines of x y z (and optional columns), or a first line naming the columns";
  EXPECT_EQ(csv_error_of(""), "points.csv" + expected);
  EXPECT_EQ(csv_error_of("# only a comment\n\n   \n"), "points.csv" + expected);
}

TEST(PointCloudText, LoadByExtension) {
  const auto dir = std::filesystem::temp_directory_path() / ("draught_test_text_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  write_file_atomic(dir / "a.XYZ", "1 2 3\n");
  write_file_atomic(dir / "a.txt", "x y z\n1 2 3\n");
  write_file_atomic(dir / "a.csv", "1,2,3\n");
  for (const char* f : {"a.XYZ", "a.txt", "a.csv"}) EXPECT_EQ(load_point_cloud(dir / f).position.at(0), glm::vec3(1, 2, 3)) << f;
  write_file_atomic(dir / "bad.csv", "1,2,3\n1,2\n");
  try {
    load_point_cloud(dir / "bad.csv");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "bad.csv").string() + ": line 2: expected 3 columns (as line 1 has), got 2");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace draught
