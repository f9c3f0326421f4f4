// The PLY reader: clouds written here in ascii and both binary byte orders, with every
// scalar type, lists and elements around the vertices, read back exactly; every refusal
// names the file, the line or byte, the element and the property.
#include "core/io/files.hpp"
#include "core/pointcloud/cloud_files.hpp"
#include "core/pointcloud/ply.hpp"
#include "core/pointcloud/point_fields.hpp"
#include "core/pointcloud/point_text.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

namespace draught {
namespace {

// Writes PLY files value by value, so tests can build well-formed and broken ones.
class PlyWriter {
 public:
  explicit PlyWriter(std::string format) : format_(std::move(format)) {}
  void header_line(const std::string& l) { header_ += l + "\n"; }
  void element(const std::string& name, std::size_t count, const std::vector<std::string>& props) {
    header_line("element " + name + " " + std::to_string(count));
    for (const auto& p : props) header_line("property " + p);
  }
  void value(const std::string& type, double v) {
    if (format_ == "ascii") {
      char buf[40];
      std::snprintf(buf, sizeof buf, "%.17g ", v);
      body_ += buf;
      return;
    }
    unsigned char b[8];
    std::size_t n = 0;
    auto put = [&](auto x) { n = sizeof x; std::memcpy(b, &x, n); };
    if (type == "char" || type == "int8") put(std::int8_t(v));
    else if (type == "uchar" || type == "uint8") put(std::uint8_t(v));
    else if (type == "short" || type == "int16") put(std::int16_t(v));
    else if (type == "ushort" || type == "uint16") put(std::uint16_t(v));
    else if (type == "int" || type == "int32") put(std::int32_t(v));
    else if (type == "uint" || type == "uint32") put(std::uint32_t(v));
    else if (type == "float" || type == "float32") put(float(v));
    else put(double(v));
    if (format_ == "binary_big_endian")
      for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
    body_.append(reinterpret_cast<const char*>(b), n);
  }
  void list(const std::string& count_type, const std::string& item_type, const std::vector<double>& items) {
    value(count_type, double(items.size()));
    for (double v : items) value(item_type, v);
  }
  void end_element() {
    if (format_ == "ascii") body_.back() = '\n';
  }
  std::size_t header_size() const { return head().size(); }
  std::string bytes() const { return head() + body_; }

 private:
  std::string head() const { return "ply\nformat " + format_ + " 1.0\ncomment written by test_ply\n" + header_ + "end_header\n"; }
  std::string format_, header_, body_;
};

struct RefPoint {
  double x, y, z, radius, temperature;
  int r, g, b;
  double vx, vy, vz;
};

std::vector<RefPoint> reference_points(std::size_t n, unsigned seed = 11) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> pos(-0.3, 0.3), rad(0.001, 0.01), temp(300, 2000), vel(-2, 2);
  std::uniform_int_distribution<int> c(0, 255);
  std::vector<RefPoint> pts;
  for (std::size_t i = 0; i < n; ++i)
    pts.push_back({pos(g), pos(g), pos(g), rad(g), temp(g), c(g), c(g), c(g), vel(g), vel(g), vel(g)});
  return pts;
}

// A face element with a list before the vertices, an edge element after them; double
// positions, float radius and temperature, uchar colours, float velocity.
std::string glass_gob(const std::string& format, const std::vector<RefPoint>& pts) {
  PlyWriter w(format);
  w.element("face", 3, {"list uchar int vertex_indices", "uchar flags"});
  w.element("vertex", pts.size(),
            {"double x", "double y", "double z", "float nx", "float radius", "float temperature", "uchar red",
             "uchar green", "uchar blue", "float vx", "float vy", "float vz"});
  w.element("edge", 1, {"int vertex1", "int vertex2"});
  for (int f = 0; f < 3; ++f) {
    w.list("uchar", "int", std::vector<double>(std::size_t(3 + f), double(f)));
    w.value("uchar", 7);
    w.end_element();
  }
  for (const auto& p : pts) {
    for (double v : {p.x, p.y, p.z}) w.value("double", v);
    w.value("float", 0.5);
    w.value("float", p.radius);
    w.value("float", p.temperature);
    for (int v : {p.r, p.g, p.b}) w.value("uchar", v);
    for (double v : {p.vx, p.vy, p.vz}) w.value("float", v);
    w.end_element();
  }
  w.value("int", 0);
  w.value("int", 1);
  w.end_element();
  return w.bytes();
}

void expect_reference(const PointCloud& c, const std::vector<RefPoint>& pts) {
  ASSERT_EQ(c.size(), pts.size());
  ASSERT_EQ(c.radius.size(), pts.size());
  ASSERT_EQ(c.temperature.size(), pts.size());
  ASSERT_EQ(c.color.size(), pts.size());
  ASSERT_EQ(c.velocity.size(), pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const RefPoint& p = pts[i];
    EXPECT_EQ(c.position[i], glm::vec3(float(p.x), float(p.y), float(p.z))) << i;
    EXPECT_EQ(c.radius[i], float(float(p.radius))) << i;
    EXPECT_EQ(c.radius_of(i), c.radius[i]);
    EXPECT_EQ(c.temperature[i], float(float(p.temperature))) << i;
    // uchar colours are sRGB: decoded to linear in double, then stored as float.
    for (int k = 0; k < 3; ++k) {
      const int v = k == 0 ? p.r : k == 1 ? p.g : p.b;
      const double s = v / 255.0, lin = s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
      EXPECT_NEAR(c.color[i][k], lin, 1e-7) << i;
    }
    EXPECT_EQ(c.velocity[i], glm::vec3(float(p.vx), float(p.vy), float(p.vz))) << i;
  }
}

const char* kFormats[] = {"ascii", "binary_little_endian", "binary_big_endian"};

std::string ply_error_of(std::string_view bytes, const std::string& name = "gob.ply") {
  try {
    parse_ply(bytes, name);
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error for this input";
  return "";
}

// A small cloud of float x y z, radius in one of the formats.
std::string simple_ply(const std::string& format, std::size_t n, const std::vector<std::string>& props = {"float x", "float y", "float z"}) {
  PlyWriter w(format);
  w.element("vertex", n, props);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < props.size(); ++k) w.value(props[k].substr(0, props[k].find(' ')), double(i) * 0.01 + double(k) * 0.001);
    w.end_element();
  }
  return w.bytes();
}

TEST(PointCloudPly, EveryFormatRoundTripsTheSameCloud) {
  const auto pts = reference_points(257);
  std::vector<PointCloud> clouds;
  for (const char* f : kFormats) {
    SCOPED_TRACE(f);
    clouds.push_back(parse_ply(glass_gob(f, pts), "gob.ply"));
    expect_reference(clouds.back(), pts);
  }
  for (std::size_t i = 1; i < clouds.size(); ++i) {
    EXPECT_EQ(clouds[i].position, clouds[0].position);
    EXPECT_EQ(clouds[i].color, clouds[0].color);
  }
}

TEST(PointCloudPly, TheSameCloudFromCsvAndXyz) {
  const auto pts = reference_points(64, 5);
  const PointCloud ply = parse_ply(glass_gob("binary_little_endian", pts), "gob.ply");
  // The same points as text: linear colours written with enough digits to read back as
  // the same floats.
  std::string csv = "# the same gob\nvx,vy,vz,x,y,z,radius,temperature,r,g,b\n", xyz;
  char buf[512];
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const auto& p = pts[i];
    const glm::vec3 c = ply.color[i];
    std::snprintf(buf, sizeof buf, "%.9g, %.9g, %.9g, %.17g, %.17g, %.17g, %.9g, %.9g, %.9g, %.9g, %.9g\n", float(p.vx),
                  float(p.vy), float(p.vz), p.x, p.y, p.z, float(p.radius), float(p.temperature), c.r, c.g, c.b);
    csv += buf;
    std::snprintf(buf, sizeof buf, "%.17g %.17g\t%.17g %.9g %.9g %.9g %.9g\n", p.x, p.y, p.z, float(p.radius), c.r, c.g, c.b);
    xyz += buf;
  }
  const PointCloud from_csv = parse_point_text(csv, "gob.csv");
  EXPECT_EQ(from_csv.position, ply.position);
  EXPECT_EQ(from_csv.radius, ply.radius);
  EXPECT_EQ(from_csv.temperature, ply.temperature);
  EXPECT_EQ(from_csv.color, ply.color);
  EXPECT_EQ(from_csv.velocity, ply.velocity);
  const PointCloud from_xyz = parse_point_text(xyz, "gob.xyz");  // 7 columns: x y z radius r g b
  EXPECT_EQ(from_xyz.position, ply.position);
  EXPECT_EQ(from_xyz.radius, ply.radius);
  EXPECT_EQ(from_xyz.color, ply.color);
  EXPECT_TRUE(from_xyz.temperature.empty());
  EXPECT_TRUE(from_xyz.velocity.empty());
}

TEST(PointCloudPly, EveryScalarTypeAndAlias) {
  const std::vector<std::string> types = {"char", "int8", "uchar", "uint8", "short", "int16", "ushort", "uint16",
                                          "int", "int32", "uint", "uint32", "float", "float32", "double", "float64"};
  for (const char* f : kFormats)
    for (const auto& t : types) {
      SCOPED_TRACE(std::string(f) + " " + t);
      PlyWriter w(f);
      // x in the type under test (small whole numbers fit every type), an unused
      // property of the same type between y and z, z a list-free double.
      w.element("vertex", 4, {t + " x", "float y", t + " unused", "double z", t + " temperature"});
      for (int i = 0; i < 4; ++i) {
        w.value(t, i * 3);
        w.value("float", 0.25 * i);
        w.value(t, 100);
        w.value("double", -1.0 / 3.0);
        w.value(t, 120 + i);
        w.end_element();
      }
      const PointCloud c = parse_ply(w.bytes(), "types.ply");
      ASSERT_EQ(c.size(), 4u);
      for (int i = 0; i < 4; ++i) {
        EXPECT_EQ(c.position[std::size_t(i)], glm::vec3(float(i * 3), 0.25f * float(i), float(-1.0 / 3.0)));
        EXPECT_EQ(c.temperature[std::size_t(i)], float(120 + i));
      }
      EXPECT_TRUE(c.radius.empty());
      EXPECT_EQ(c.radius_of(2), c.default_radius);
    }
}

TEST(PointCloudPly, ColoursBySpellingAndType) {
  for (const char* f : kFormats) {
    SCOPED_TRACE(f);
    PlyWriter w(f);
    w.element("vertex", 2, {"float x", "float y", "float z", "ushort diffuse_red", "ushort diffuse_green", "ushort diffuse_blue"});
    for (int i = 0; i < 2; ++i) {
      for (int k = 0; k < 3; ++k) w.value("float", k);
      w.value("ushort", 0);
      w.value("ushort", 65535);
      w.value("ushort", 32768);
      w.end_element();
    }
    const PointCloud c = parse_ply(w.bytes(), "c.ply");
    ASSERT_EQ(c.color.size(), 2u);
    EXPECT_EQ(c.color[1].r, 0.0f);
    EXPECT_FLOAT_EQ(c.color[1].g, 1.0f);
    EXPECT_NEAR(c.color[1].b, std::pow((32768 / 65535.0 + 0.055) / 1.055, 2.4), 1e-7);  // sRGB, not 0.5

    PlyWriter lin(f);  // float colours are linear, as given
    lin.element("vertex", 1, {"float x", "float y", "float z", "float r", "float g", "float b"});
    for (double v : {0.0, 0.0, 0.0, 0.5, 0.25, 1.0}) lin.value("float", v);
    lin.end_element();
    EXPECT_EQ(parse_ply(lin.bytes(), "lin.ply").color.at(0), glm::vec3(0.5f, 0.25f, 1.0f));
  }
}

TEST(PointCloudPly, VelocityAndRadiusAliases) {
  PlyWriter w("ascii");
  w.element("vertex", 1, {"float x", "float y", "float z", "float velocity_x", "float velocity_y", "float velocity_z", "float pscale"});
  for (double v : {1.0, 2.0, 3.0, -1.0, 0.5, 4.0, 0.003}) w.value("float", v);
  w.end_element();
  const PointCloud c = parse_ply(w.bytes(), "v.ply");
  EXPECT_EQ(c.velocity.at(0), glm::vec3(-1.0f, 0.5f, 4.0f));
  EXPECT_EQ(c.radius.at(0), 0.003f);
}

TEST(PointCloudPly, CrlfHeaderAndZeroVertices) {
  std::string s = "ply\r\nformat ascii 1.0\r\nelement vertex 1\r\nproperty float x\r\nproperty float y\r\nproperty float z\r\nend_header\r\n1 2 3\r\n";
  EXPECT_EQ(parse_ply(s, "crlf.ply").position.at(0), glm::vec3(1, 2, 3));
  // No points is a cloud of none (a simulation's frame before the pour).
  EXPECT_EQ(parse_ply(simple_ply("binary_little_endian", 0), "none.ply").size(), 0u);
}

TEST(PointCloudPly, TruncatedBinaryBodyNamesTheByte) {
  for (const char* f : {"binary_little_endian", "binary_big_endian"}) {
    const std::string full = simple_ply(f, 200);
    const std::size_t header = full.size() - 200 * 12;
    // Vertex 101's z begins at header + 101 * 12 + 8; cut the file there.
    EXPECT_EQ(ply_error_of(std::string_view(full).substr(0, header + 101 * 12 + 8)),
              "gob.ply: byte " + std::to_string(header + 101 * 12 + 8) +
                  " (vertex 101, property z): the file ends; expected 4 more bytes");
    EXPECT_EQ(ply_error_of(std::string_view(full).substr(0, header + 101 * 12 + 9)),
              "gob.ply: byte " + std::to_string(header + 101 * 12 + 8) +
                  " (vertex 101, property z): the file ends; expected 3 more bytes");
  }
}

TEST(PointCloudPly, TruncatedListBeforeTheVertices) {
  PlyWriter w("binary_little_endian");
  w.element("face", 2, {"list uchar int vertex_indices"});
  w.element("vertex", 1, {"float x", "float y", "float z"});
  w.list("uchar", "int", {0, 1, 2});
  w.list("uchar", "int", {0, 1, 2, 3});  // 17 bytes; the file keeps 1 + 4 of them
  const std::string s = w.bytes();
  const std::size_t second = w.header_size() + 13;
  EXPECT_EQ(ply_error_of(std::string_view(s).substr(0, second + 5)),
            "gob.ply: byte " + std::to_string(second + 1) +
                " (face 1, property vertex_indices): the file ends inside a list of 4 items; expected 12 more bytes");
}

TEST(PointCloudPly, AsciiBodyErrorsNameTheLine) {
  const std::string head = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                           "property float radius\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  EXPECT_EQ(ply_error_of(head + "0 0 0 0.01 1 2 3\n0 abc 0 0.01 1 2 3\n"),
            "gob.ply: line 13 (vertex 1, property y): expected a number (float), got \"abc\"");
  EXPECT_EQ(ply_error_of(head + "0 0 0 0.01 1 2 3\n\n0 0 nan 0.01 1 2 3\n"),
            "gob.ply: line 14 (vertex 1, property z): expected a finite coordinate in [-1e6, 1e6] m, got nan");
  EXPECT_EQ(ply_error_of(head + "inf 0 0 0.01 1 2 3\n"),
            "gob.ply: line 12 (vertex 0, property x): expected a finite coordinate in [-1e6, 1e6] m, got inf");
  EXPECT_EQ(ply_error_of(head + "0 0 0 -0.5 1 2 3\n"),
            "gob.ply: line 12 (vertex 0, property radius): expected a radius in [1e-9, 1e6] (the file's units), got -0.5");
  EXPECT_EQ(ply_error_of(head + "0 0 0 0.01 1 300 3\n"),
            "gob.ply: line 12 (vertex 0, property green): expected an integer in [0, 255] (uchar), got \"300\"");
  EXPECT_EQ(ply_error_of(head + "0 0 0 0.01 1 2 3 4\n"),
            "gob.ply: line 12 (vertex 0): more values than the 7 properties of 'vertex': expected the line to end, got \"4\"");
  EXPECT_EQ(ply_error_of(head + "0 0 0 0.01 1 2\n"),
            "gob.ply: line 12 (vertex 0, property blue): the line ends: expected a value");
  EXPECT_EQ(ply_error_of(head + "0 0 0 0.01 1 2 3\n1 1 1 0.01 1 2 3\n"),
            "gob.ply: line 14: the file ends after 2 of 3 vertex elements: expected vertex 2");
}

TEST(PointCloudPly, BinaryValueErrorsNameTheByte) {
  PlyWriter w("binary_big_endian");
  w.element("vertex", 3, {"float x", "float y", "float z", "double radius", "float temperature"});
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) w.value("float", 0.1 * k);
    w.value("double", i == 2 ? -0.002 : 0.002);
    w.value("float", i == 1 ? 12000 : 900);
    w.end_element();
  }
  // Vertex 1's temperature (12000 K) comes first: 24 bytes a vertex, 20 into it.
  EXPECT_EQ(ply_error_of(w.bytes()), "gob.ply: byte " + std::to_string(w.header_size() + 24 + 20) +
                                     " (vertex 1, property temperature): expected a temperature in [0, 10000] K, got 12000");
  PlyWriter n("binary_little_endian");
  n.element("vertex", 1, {"float x", "float y", "float z"});
  n.value("float", 0);
  n.value("float", std::nan(""));
  n.value("float", 0);
  EXPECT_EQ(ply_error_of(n.bytes()), "gob.ply: byte " + std::to_string(n.header_size() + 4) +
                                     " (vertex 0, property y): expected a finite coordinate in [-1e6, 1e6] m, got nan");
}

TEST(PointCloudPly, HeaderErrorsNameTheLine) {
  const std::string xyz = "property float x\nproperty float y\nproperty float z\n";
  EXPECT_EQ(ply_error_of(""), "gob.ply: the file is empty: expected a PLY header starting with 'ply'");
  EXPECT_EQ(ply_error_of("PLY\n"), "gob.ply: line 1: expected 'ply' (a PLY file starts with it), got \"PLY\"");
  EXPECT_EQ(ply_error_of("ply\nformat binary_middle_endian 1.0\n"),
            "gob.ply: line 2: unknown format \"binary_middle_endian\": expected ascii, binary_little_endian or binary_big_endian");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 2.0\n"), "gob.ply: line 2: unknown PLY version \"2.0\": expected 1.0");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\n"),
            "gob.ply: line 4: unknown type \"float128\": expected char, uchar, short, ushort, int, uint, float, double "
            "(or int8 ... float64)");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nproperty float x\n"),
            "gob.ply: line 3: a property before any element: expected 'element NAME COUNT' first");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement vertex 1\n" + xyz),
            "gob.ply: line 6: the file ends inside the header: expected 'end_header'");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement vertex many\n"),
            "gob.ply: line 3: element \"vertex\": expected a count (a whole number), got \"many\"");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nvertices 3\n"),
            "gob.ply: line 3: expected comment, format, element, property or end_header, got \"vertices\"");
  // Bytes of the file are echoed escaped and as valid UTF-8 (a fuzzer's finding).
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\n\xff\x1b\n"),
            "gob.ply: line 3: expected comment, format, element, property or end_header, got \"\xef\xbf\xbd\\u001b\"");
  EXPECT_EQ(ply_error_of("ply\nelement vertex 1\n"), "gob.ply: line 2: an element before the 'format' line: expected format first");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement face 1\nproperty list float int i\nend_header\n"),
            "gob.ply: line 4: list \"i\": expected an integer count type, got \"float\"");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement face 0\nproperty uchar n\nend_header\n"),
            "gob.ply: line 5: the header has no element 'vertex': expected the points as 'element vertex N'");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n"),
            "gob.ply: line 3: element 'vertex': no 'z': expected x, y and z");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "property float red\nend_header\n0 0 0 1\n"),
            "gob.ply: line 3: element 'vertex': a colour is given in part: expected also 'g', 'b'");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "property float radius\nproperty float pscale\nend_header\n"),
            "gob.ply: line 3: element 'vertex': both 'radius' and 'pscale' give the radius: expected one of them");
  EXPECT_EQ(ply_error_of("ply\nformat ascii 1.0\nelement vertex 1\n" + xyz + "property int red\nproperty int green\nproperty int blue\nend_header\n"),
            "gob.ply: line 3: vertex property 'red' is int: expected uchar or ushort (sRGB-encoded), float or double (linear 0..1)");
}

TEST(PointCloudPly, CountsTooLargeAreRefusedBeforeReading) {
  EXPECT_EQ(ply_error_of("ply\nformat binary_little_endian 1.0\nelement vertex 4194305\nproperty float x\nproperty float y\nproperty float z\nend_header\n"),
            "gob.ply: line 3: 4194305 vertices: expected at most 4194304 (the limit of a point cloud)");
  EXPECT_EQ(ply_error_of("ply\nformat binary_little_endian 1.0\nelement vertex 99999999999999999999\n"),
            "gob.ply: line 3: element \"vertex\": expected a count (a whole number), got \"99999999999999999999\"");
  // Within the limit but far more than the bytes that follow: refused at once, at the
  // first missing byte.
  const std::string head = "ply\nformat binary_little_endian 1.0\nelement vertex 4000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  EXPECT_EQ(ply_error_of(head + std::string(30, '\0')),
            "gob.ply: byte " + std::to_string(head.size() + 28) + " (vertex 2, property y): the file ends; expected 2 more bytes");
  // Ascii and lists are walked (with memory for no more than the bytes can hold) and fail
  // at the first missing line or byte.
  const std::string ahead = "ply\nformat ascii 1.0\nelement vertex 4000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  EXPECT_EQ(ply_error_of(ahead + "0 0 0\n"), "gob.ply: line 9: the file ends after 1 of 4000000 vertex elements: expected vertex 1");
  const std::string faces = "ply\nformat binary_little_endian 1.0\nelement face 4000000000\nproperty list uchar int i\n"
                            "element vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n";
  EXPECT_EQ(ply_error_of(faces + std::string(64, '\0')),  // 64 empty lists, then nothing
            "gob.ply: byte " + std::to_string(faces.size() + 64) + " (face 64, property i): the file ends; expected 1 more bytes");
}

TEST(PointCloudPly, ElementsAfterTheVerticesAreIgnored) {
  const std::string s = simple_ply("ascii", 2) ;
  // An element after the vertices whose data is missing or broken does not matter.
  std::string with_after = s;
  with_after.insert(with_after.find("end_header"), "element material 5\nproperty float shininess\n");
  EXPECT_EQ(parse_ply(with_after + "broken\n", "after.ply").size(), 2u);
}

TEST(PointCloudPly, LoadByExtension) {
  const auto dir = std::filesystem::temp_directory_path() / ("draught_test_ply_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto pts = reference_points(10);
  write_file_atomic(dir / "gob.PLY", glass_gob("binary_big_endian", pts));
  expect_reference(load_point_cloud(dir / "gob.PLY"), pts);
  write_file_atomic(dir / "gob.obj", "v 0 0 0\n");
  try {
    load_point_cloud(dir / "gob.obj");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), (dir / "gob.obj").string() + ": unknown point cloud extension \".obj\": expected .ply, .xyz, .csv or .txt");
  }
  std::filesystem::create_directories(dir / "folder.ply");
  try {
    load_point_cloud(dir / "folder.ply");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find((dir / "folder.ply").string() + ": is a directory"), std::string::npos) << e.what();
  }
  const std::string whole = simple_ply("binary_little_endian", 30);
  write_file_atomic(dir / "cut.ply", whole.substr(0, whole.size() - 5));
  try {
    load_point_cloud(dir / "cut.ply");
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind((dir / "cut.ply").string() + ": byte ", 0), 0u) << e.what();
  }
  std::filesystem::remove_all(dir);
}

// Load times of a million points (run with --gtest_also_run_disabled_tests).
TEST(PointCloudPly, DISABLED_BenchmarkMillionPoints) {
  const auto dir = std::filesystem::temp_directory_path() / ("draught_bench_ply_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const auto pts = reference_points(1000000);
  PlyWriter w("binary_little_endian");
  w.element("vertex", pts.size(), {"float x", "float y", "float z", "float radius", "float temperature", "uchar red", "uchar green", "uchar blue"});
  std::string csv = "x,y,z,radius,temperature,r,g,b\n";
  char buf[256];
  for (const auto& p : pts) {
    for (double v : {p.x, p.y, p.z, p.radius, p.temperature}) w.value("float", v);
    for (int v : {p.r, p.g, p.b}) w.value("uchar", v);
    std::snprintf(buf, sizeof buf, "%.7g,%.7g,%.7g,%.5g,%.6g,%.5g,%.5g,%.5g\n", p.x, p.y, p.z, p.radius, p.temperature,
                  p.r / 255.0, p.g / 255.0, p.b / 255.0);
    csv += buf;
  }
  write_file_atomic(dir / "million.ply", w.bytes());
  write_file_atomic(dir / "million.csv", csv);
  for (const char* f : {"million.ply", "million.csv"}) {
    const auto t0 = std::chrono::steady_clock::now();
    const PointCloud c = load_point_cloud(dir / f);
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(c.size(), pts.size());
    std::printf("%s: %zu bytes, %zu points in %.1f ms\n", f, std::size_t(std::filesystem::file_size(dir / f)), c.size(), ms);
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace draught
