#include "core/pointcloud/ply.hpp"

#include "core/io/files.hpp"
#include "core/pointcloud/point_fields.hpp"
#include "core/text/echo.hpp"
#include "core/text/trim.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <optional>
#include <vector>

namespace draught {

namespace {

enum class Format { Ascii, Little, Big };
enum class Type { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct TypeName {
  const char* name;
  Type type;
};
constexpr TypeName kTypeNames[] = {
    {"char", Type::Int8},      {"int8", Type::Int8},       {"uchar", Type::UInt8},   {"uint8", Type::UInt8},
    {"short", Type::Int16},    {"int16", Type::Int16},     {"ushort", Type::UInt16}, {"uint16", Type::UInt16},
    {"int", Type::Int32},      {"int32", Type::Int32},     {"uint", Type::UInt32},   {"uint32", Type::UInt32},
    {"float", Type::Float32},  {"float32", Type::Float32}, {"double", Type::Float64}, {"float64", Type::Float64},
};

std::size_t size_of(Type t) {
  switch (t) {
    case Type::Int8: case Type::UInt8: return 1;
    case Type::Int16: case Type::UInt16: return 2;
    case Type::Int32: case Type::UInt32: case Type::Float32: return 4;
    case Type::Float64: return 8;
  }
  return 0;
}
bool integral(Type t) { return t != Type::Float32 && t != Type::Float64; }
const char* type_name(Type t) {
  for (const auto& n : kTypeNames)
    if (n.type == t) return n.name;
  return "?";
}
// The range of an integral type, for ascii values.
std::pair<double, double> range_of(Type t) {
  switch (t) {
    case Type::Int8: return {-128, 127};
    case Type::UInt8: return {0, 255};
    case Type::Int16: return {-32768, 32767};
    case Type::UInt16: return {0, 65535};
    case Type::Int32: return {-2147483648.0, 2147483647.0};
    case Type::UInt32: return {0, 4294967295.0};
    default: return {-HUGE_VAL, HUGE_VAL};
  }
}

struct Property {
  std::string name;
  Type type = Type::Float32;    // the items' type for a list
  bool list = false;
  Type count_type = Type::UInt8;
};

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> props;
  std::size_t line = 0;  // of its "element" line
  // The bytes of one element in a binary body when it has no lists, else nullopt.
  std::optional<std::size_t> fixed_size() const {
    std::size_t s = 0;
    for (const auto& p : props) {
      if (p.list) return std::nullopt;
      s += size_of(p.type);
    }
    return s;
  }
  // The fewest bytes one element can take in a binary body (lists empty).
  std::size_t min_size() const {
    std::size_t s = 0;
    for (const auto& p : props) s += size_of(p.list ? p.count_type : p.type);
    return s;
  }
};

// A name from the header as messages show it: capped, valid UTF-8, no control characters.
std::string shown_name(std::string_view s) {
  std::string out = make_valid_utf8(utf8_prefix(s, kEchoBytes));
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7F) c = '?';
  return out;
}

std::vector<std::string_view> words(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\v' || s[i] == '\f')) ++i;
    const std::size_t start = i;
    while (i < s.size() && !(s[i] == ' ' || s[i] == '\t' || s[i] == '\r' || s[i] == '\v' || s[i] == '\f')) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

bool parse_count(std::string_view t, std::uint64_t& v) {
  if (t.empty() || t.size() > 19) return false;  // 19 digits cannot overflow 64 bits
  for (char c : t)
    if (c < '0' || c > '9') return false;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v);
  return r.ec == std::errc() && r.ptr == t.data() + t.size();
}

double read_binary(const char* p, Type t, bool swap) {
  unsigned char b[8];
  const std::size_t n = size_of(t);
  std::memcpy(b, p, n);
  if (swap)
    for (std::size_t i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
  switch (t) {
    case Type::Int8: { std::int8_t v; std::memcpy(&v, b, 1); return v; }
    case Type::UInt8: return b[0];
    case Type::Int16: { std::int16_t v; std::memcpy(&v, b, 2); return v; }
    case Type::UInt16: { std::uint16_t v; std::memcpy(&v, b, 2); return v; }
    case Type::Int32: { std::int32_t v; std::memcpy(&v, b, 4); return v; }
    case Type::UInt32: { std::uint32_t v; std::memcpy(&v, b, 4); return v; }
    case Type::Float32: { float v; std::memcpy(&v, b, 4); return v; }
    case Type::Float64: { double v; std::memcpy(&v, b, 8); return v; }
  }
  return 0;
}

// sRGB-encoded 8-bit channels decoded once.
const std::array<double, 256>& srgb8_table() {
  static const std::array<double, 256> t = [] {
    std::array<double, 256> a{};
    for (int i = 0; i < 256; ++i) a[std::size_t(i)] = srgb_to_linear(i / 255.0);
    return a;
  }();
  return t;
}

class PlyReader {
 public:
  PlyReader(std::string_view bytes, const std::string& name) : s_(bytes), name_(name) {}

  PointCloud read() {
    read_header();
    std::size_t vertex = 0;
    while (elements_[vertex].name != "vertex") ++vertex;
    if (format_ == Format::Ascii) {
      std::size_t pos = body_, line = header_lines_;
      for (std::size_t e = 0; e < vertex; ++e) skip_ascii(elements_[e], pos, line);
      return read_ascii_vertices(elements_[vertex], pos, line);
    }
    std::size_t pos = body_;
    for (std::size_t e = 0; e < vertex; ++e) skip_binary(elements_[e], pos);
    return read_binary_vertices(elements_[vertex], pos);
  }

 private:
  [[noreturn]] void fail(const std::string& where, const std::string& what) const {
    throw InputError(name_ + ": " + where + ": " + what);
  }
  static std::string at_line(std::size_t line) { return "line " + std::to_string(line); }
  static std::string at_byte(std::size_t byte) { return "byte " + std::to_string(byte); }
  static std::string in(const Element& e, std::uint64_t i, const Property* p) {
    std::string s = " (" + e.name + " " + std::to_string(i);
    if (p) s += ", property " + p->name;
    return s + ")";
  }

  void read_header() {
    if (s_.empty()) throw InputError(name_ + ": the file is empty: expected a PLY header starting with 'ply'");
    std::size_t pos = 0, line = 0;
    bool ended = false, have_format = false;
    while (pos < s_.size()) {
      const std::size_t nl = s_.find('\n', pos);
      const std::size_t end = nl == std::string_view::npos ? s_.size() : nl;
      const std::string_view text = s_.substr(pos, end - pos);
      pos = nl == std::string_view::npos ? s_.size() : nl + 1;
      ++line;
      const std::vector<std::string_view> w = words(text);
      if (line == 1) {
        if (trim(text) != "ply")
          fail(at_line(1), "expected 'ply' (a PLY file starts with it), got " + quote_token(trim(text)));
        continue;
      }
      if (w.empty()) fail(at_line(line), "an empty header line: expected comment, format, element, property or end_header");
      const std::string_view key = w[0];
      if (key == "comment" || key == "obj_info") continue;
      if (key == "format") {
        if (have_format) fail(at_line(line), "a second 'format' line: expected one");
        if (w.size() != 3) fail(at_line(line), "expected 'format ascii|binary_little_endian|binary_big_endian 1.0'");
        if (w[1] == "ascii") format_ = Format::Ascii;
        else if (w[1] == "binary_little_endian") format_ = Format::Little;
        else if (w[1] == "binary_big_endian") format_ = Format::Big;
        else fail(at_line(line), "unknown format " + quote_token(w[1]) + ": expected ascii, binary_little_endian or binary_big_endian");
        if (w[2] != "1.0") fail(at_line(line), "unknown PLY version " + quote_token(w[2]) + ": expected 1.0");
        have_format = true;
      } else if (key == "element") {
        if (!have_format) fail(at_line(line), "an element before the 'format' line: expected format first");
        if (w.size() != 3) fail(at_line(line), "expected 'element NAME COUNT'");
        Element e;
        e.name = shown_name(w[1]);
        e.line = line;
        if (!parse_count(w[2], e.count))
          fail(at_line(line), "element " + quote_token(w[1]) + ": expected a count (a whole number), got " + quote_token(w[2]));
        for (const auto& other : elements_)
          if (other.name == e.name) fail(at_line(line), "element " + quote_token(w[1]) + " is declared twice: expected it once");
        if (elements_.size() == kMaxPlyElements)
          fail(at_line(line), "more than " + std::to_string(kMaxPlyElements) + " elements: expected at most that many");
        elements_.push_back(std::move(e));
      } else if (key == "property") {
        if (elements_.empty()) fail(at_line(line), "a property before any element: expected 'element NAME COUNT' first");
        Element& e = elements_.back();
        Property p;
        std::string_view pname;
        if (w.size() >= 2 && w[1] == "list") {
          if (w.size() != 5) fail(at_line(line), "expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
          p.list = true;
          p.count_type = type_of(w[2], line);
          p.type = type_of(w[3], line);
          if (!integral(p.count_type))
            fail(at_line(line), "list " + quote_token(w[4]) + ": expected an integer count type, got " + quote_token(w[2]));
          pname = w[4];
        } else {
          if (w.size() != 3) fail(at_line(line), "expected 'property TYPE NAME' or 'property list COUNT_TYPE ITEM_TYPE NAME'");
          p.type = type_of(w[1], line);
          pname = w[2];
        }
        p.name = shown_name(pname);
        if (e.props.size() == kMaxPlyProperties)
          fail(at_line(line), "element '" + e.name + "' has more than " + std::to_string(kMaxPlyProperties) +
                                  " properties: expected at most that many");
        e.props.push_back(std::move(p));
      } else if (key == "end_header") {
        if (w.size() != 1) fail(at_line(line), "expected 'end_header' alone on its line");
        ended = true;
        break;
      } else {
        fail(at_line(line), "expected comment, format, element, property or end_header, got " + quote_token(key));
      }
    }
    if (!ended) fail(at_line(line), "the file ends inside the header: expected 'end_header'");
    if (!have_format) fail(at_line(line), "the header has no 'format' line: expected one before the elements");
    body_ = pos;
    header_lines_ = line;
    bool vertex = false;
    for (const auto& e : elements_) {
      if (e.props.empty() && e.count > 0)
        fail(at_line(e.line), "element '" + e.name + "' has no properties: expected at least one");
      if (e.name == "vertex") {
        vertex = true;
        check_vertex_header(e);
      }
    }
    if (!vertex) fail(at_line(line), "the header has no element 'vertex': expected the points as 'element vertex N'");
  }

  Type type_of(std::string_view t, std::size_t line) const {
    for (const auto& n : kTypeNames)
      if (t == n.name) return n.type;
    fail(at_line(line), "unknown type " + quote_token(t) +
                            ": expected char, uchar, short, ushort, int, uint, float, double (or int8 ... float64)");
  }

  void check_vertex_header(const Element& e) {
    if (e.count > kMaxCloudPoints)
      fail(at_line(e.line), std::to_string(e.count) + " vertices: expected at most " + std::to_string(kMaxCloudPoints) +
                                " (the limit of a point cloud)");
    std::vector<std::string_view> names;
    for (const auto& p : e.props) names.push_back(p.name);
    const std::string problem = resolve_point_fields(names, true, fields_);
    if (!problem.empty()) fail(at_line(e.line), "element 'vertex': " + problem);
    for (int f = 0; f < kPointFieldCount; ++f) {
      const int c = fields_.column[std::size_t(f)];
      if (c < 0) continue;
      const Property& p = e.props[std::size_t(c)];
      if (p.list) fail(at_line(e.line), "vertex property '" + p.name + "' is a list: expected a scalar");
      const bool colour = f >= int(PointField::Red) && f <= int(PointField::Blue);
      if (colour && integral(p.type) && p.type != Type::UInt8 && p.type != Type::UInt16)
        fail(at_line(e.line), "vertex property '" + p.name + "' is " + type_name(p.type) +
                                  ": expected uchar or ushort (sRGB-encoded), float or double (linear 0..1)");
    }
    // Field of each property, -1 when skipped.
    field_of_.assign(e.props.size(), -1);
    for (int f = 0; f < kPointFieldCount; ++f)
      if (fields_.column[std::size_t(f)] >= 0) field_of_[std::size_t(fields_.column[std::size_t(f)])] = f;
  }

  // The value a vertex property gives its field: 8- and 16-bit colours are sRGB-encoded.
  double field_value(int field, Type t, double raw) const {
    if (field >= int(PointField::Red) && field <= int(PointField::Blue)) {
      if (t == Type::UInt8) return srgb8_table()[std::size_t(raw)];
      if (t == Type::UInt16) return srgb_to_linear(raw / 65535.0);
    }
    return raw;
  }

  // ---- ascii: one element per line; blank lines are skipped.

  // The next non-blank line, or false at the end of the file.
  bool next_line(std::size_t& pos, std::size_t& line, std::string_view& text) const {
    while (pos < s_.size()) {
      const std::size_t nl = s_.find('\n', pos);
      const std::size_t end = nl == std::string_view::npos ? s_.size() : nl;
      text = s_.substr(pos, end - pos);
      pos = nl == std::string_view::npos ? s_.size() : nl + 1;
      ++line;
      if (!trim(text).empty()) return true;
    }
    return false;
  }

  std::string_view element_line(const Element& e, std::uint64_t i, std::size_t& pos, std::size_t& line) const {
    std::string_view text;
    if (!next_line(pos, line, text))
      fail(at_line(line + 1), "the file ends after " + std::to_string(i) + " of " + std::to_string(e.count) + " " +
                                  e.name + " elements: expected " + e.name + " " + std::to_string(i));
    return text;
  }

  // An ascii value of property `p` (a list's count when `count`), checked against its type.
  double ascii_value(std::string_view tok, Type t, const Element& e, std::uint64_t i, const Property& p,
                     std::size_t line, bool count) const {
    const std::string where = at_line(line) + in(e, i, &p);
    if (tok.empty()) fail(where, std::string("the line ends: expected ") + (count ? "the list's count" : "a value"));
    double v;
    if (!parse_number(tok, v)) fail(where, std::string("expected a number (") + type_name(t) + "), got " + quote_token(tok));
    if (integral(t)) {
      const auto [lo, hi] = range_of(t);
      if (!(v == std::floor(v) && v >= lo && v <= hi))
        fail(where, std::string("expected ") + (count ? "a list count" : "an integer") + " in [" + number_text(lo) + ", " +
                        number_text(hi) + "] (" + type_name(t) + "), got " + quote_token(tok));
      if (count && v < 0) fail(where, "expected a list count of at least 0, got " + quote_token(tok));
    }
    return v;
  }

  // Reads one element's values from its line; values[k] of scalar property k (lists read
  // and dropped).
  void ascii_element(const Element& e, std::uint64_t i, std::size_t& pos, std::size_t& line, double* values) const {
    const std::string_view text = element_line(e, i, pos, line);
    std::size_t c = 0;
    auto token = [&]() {
      while (c < text.size() && (text[c] == ' ' || text[c] == '\t' || text[c] == '\r' || text[c] == '\v' || text[c] == '\f')) ++c;
      const std::size_t start = c;
      while (c < text.size() && !(text[c] == ' ' || text[c] == '\t' || text[c] == '\r' || text[c] == '\v' || text[c] == '\f')) ++c;
      return text.substr(start, c - start);
    };
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      const Property& p = e.props[k];
      if (!p.list) {
        const double v = ascii_value(token(), p.type, e, i, p, line, false);
        if (values) values[k] = v;
        continue;
      }
      const double n = ascii_value(token(), p.count_type, e, i, p, line, true);
      for (double j = 0; j < n; ++j) ascii_value(token(), p.type, e, i, p, line, false);
    }
    const std::string_view extra = token();
    if (!extra.empty())
      fail(at_line(line) + in(e, i, nullptr), "more values than the " + std::to_string(e.props.size()) +
                                                   " properties of '" + e.name + "': expected the line to end, got " +
                                                   quote_token(extra));
  }

  void skip_ascii(const Element& e, std::size_t& pos, std::size_t& line) const {
    // A count beyond the file's lines fails at the first missing one.
    for (std::uint64_t i = 0; i < e.count; ++i) ascii_element(e, i, pos, line, nullptr);
  }

  PointCloud read_ascii_vertices(const Element& e, std::size_t pos, std::size_t line) const {
    // Memory for no more vertices than the rest can hold (a value and a separator each);
    // a count beyond the file's lines fails at the first missing one.
    PointCloudBuilder cloud(fields_, std::min<std::size_t>(std::size_t(e.count), (s_.size() - pos + 1) / (2 * e.props.size())));
    std::vector<double> values(e.props.size());
    std::array<double, kPointFieldCount> point{};
    for (std::uint64_t i = 0; i < e.count; ++i) {
      ascii_element(e, i, pos, line, values.data());
      for (std::size_t k = 0; k < e.props.size(); ++k)
        if (field_of_[k] >= 0) point[std::size_t(field_of_[k])] = field_value(field_of_[k], e.props[k].type, values[k]);
      if (const int bad = cloud.add(point); bad >= 0) {
        const Property& p = e.props[std::size_t(fields_.column[std::size_t(bad)])];
        fail(at_line(line) + in(e, i, &p), std::string("expected ") + point_value_expected(PointField(bad), point[std::size_t(bad)]) +
                                             ", got " + number_text(values[std::size_t(fields_.column[std::size_t(bad)])]));
      }
    }
    return cloud.take();
  }

  // ---- binary

  // The error for a fixed-size element whose `count` records do not fit the `avail` bytes
  // from `start`: where the first missing byte would be, in which element and property.
  [[noreturn]] void truncated(const Element& e, std::size_t size, std::size_t start, std::size_t avail) const {
    const std::uint64_t i = avail / size;
    const std::size_t off = avail % size;
    std::size_t at = 0;
    for (const Property& p : e.props) {
      const std::size_t n = size_of(p.type);
      if (off < at + n)
        fail(at_byte(start + std::size_t(i) * size + at) + in(e, i, &p),
             "the file ends; expected " + std::to_string(n - (off - at)) + " more bytes");
      at += n;
    }
    fail(at_byte(start + avail), "the file ends");  // not reached: off < size
  }

  // Reads a binary scalar at pos, or fails naming it.
  double binary_value(std::size_t& pos, Type t, const Element& e, std::uint64_t i, const Property& p) const {
    const std::size_t n = size_of(t);
    if (s_.size() - pos < n)
      fail(at_byte(pos) + in(e, i, &p), "the file ends; expected " + std::to_string(n - (s_.size() - pos)) + " more bytes");
    const double v = read_binary(s_.data() + pos, t, format_ == Format::Big);
    pos += n;
    return v;
  }

  // Steps over a binary list (its count, then its items).
  void skip_binary_list(std::size_t& pos, const Element& e, std::uint64_t i, const Property& p) const {
    const std::size_t count_at = pos;
    const double n = binary_value(pos, p.count_type, e, i, p);
    if (n < 0) fail(at_byte(count_at) + in(e, i, &p), "expected a list count of at least 0, got " + number_text(n));
    const std::size_t bytes = std::size_t(n) * size_of(p.type);
    if (s_.size() - pos < bytes)
      fail(at_byte(pos) + in(e, i, &p), "the file ends inside a list of " + number_text(n) + " items; expected " +
                                            std::to_string(bytes - (s_.size() - pos)) + " more bytes");
    pos += bytes;
  }

  void binary_element(const Element& e, std::uint64_t i, std::size_t& pos, double* values) const {
    for (std::size_t k = 0; k < e.props.size(); ++k) {
      const Property& p = e.props[k];
      if (p.list) skip_binary_list(pos, e, i, p);
      else if (values) values[k] = binary_value(pos, p.type, e, i, p);
      else binary_value(pos, p.type, e, i, p);
    }
  }

  void skip_binary(const Element& e, std::size_t& pos) const {
    if (e.count == 0) return;  // (an element without properties has count 0, checked)
    const std::size_t avail = s_.size() - pos;
    if (const auto size = e.fixed_size()) {
      if (e.count > avail / *size) truncated(e, *size, pos, avail);
      pos += std::size_t(e.count) * *size;
      return;
    }
    // Each element takes at least one byte, so a count beyond the file fails at its end.
    for (std::uint64_t i = 0; i < e.count; ++i) binary_element(e, i, pos, nullptr);
  }

  PointCloud read_binary_vertices(const Element& e, std::size_t pos) const {
    const std::size_t avail = s_.size() - pos;
    const auto size = e.fixed_size();
    if (size && e.count > avail / *size) truncated(e, *size, pos, avail);
    // (with lists: memory for no more vertices than the bytes left can hold)
    PointCloudBuilder cloud(fields_, size ? std::size_t(e.count) : std::min<std::size_t>(std::size_t(e.count), avail / e.min_size()));
    std::vector<double> values(e.props.size());
    std::vector<std::size_t> offsets(e.props.size());
    std::array<double, kPointFieldCount> point{};
    for (std::uint64_t i = 0; i < e.count; ++i) {
      if (size) {  // the common case: no lists, so no bounds to check within the record
        std::size_t at = pos;
        for (std::size_t k = 0; k < e.props.size(); ++k) {
          offsets[k] = at;
          values[k] = read_binary(s_.data() + at, e.props[k].type, format_ == Format::Big);
          at += size_of(e.props[k].type);
        }
        pos = at;
      } else {
        for (std::size_t k = 0; k < e.props.size(); ++k) {
          offsets[k] = pos;
          const Property& p = e.props[k];
          if (p.list) skip_binary_list(pos, e, i, p);
          else values[k] = binary_value(pos, p.type, e, i, p);
        }
      }
      for (std::size_t k = 0; k < e.props.size(); ++k)
        if (field_of_[k] >= 0) point[std::size_t(field_of_[k])] = field_value(field_of_[k], e.props[k].type, values[k]);
      if (const int bad = cloud.add(point); bad >= 0) {
        const std::size_t k = std::size_t(fields_.column[std::size_t(bad)]);
        fail(at_byte(offsets[k]) + in(e, i, &e.props[k]),
             std::string("expected ") + point_value_expected(PointField(bad), point[std::size_t(bad)]) + ", got " +
                 number_text(values[k]));
      }
    }
    return cloud.take();
  }

  std::string_view s_;
  const std::string& name_;
  Format format_ = Format::Ascii;
  std::vector<Element> elements_;
  std::size_t body_ = 0, header_lines_ = 0;
  PointFieldColumns fields_;
  std::vector<int> field_of_;
};

}  // namespace

PointCloud parse_ply(std::string_view bytes, const std::string& name) { return PlyReader(bytes, name).read(); }

}  // namespace draught
