#include "core/pointcloud/point_text.hpp"

#include "core/io/files.hpp"
#include "core/pointcloud/point_fields.hpp"
#include "core/text/echo.hpp"
#include "core/text/suggest.hpp"
#include "core/text/trim.hpp"

#include <array>
#include <optional>
#include <vector>

namespace draught {

namespace {

bool space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Splits a line into at most `max` + 1 columns (one more than can be right, enough to
// say there are too many): by commas when it has one, else by runs of whitespace.
void split(std::string_view line, std::size_t max, std::vector<std::string_view>& out) {
  out.clear();
  if (line.find(',') != std::string_view::npos) {
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = line.find(',', start);
      out.push_back(trim(line.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start)));
      if (comma == std::string_view::npos || out.size() > max) return;
      start = comma + 1;
    }
  }
  std::size_t i = 0;
  while (i < line.size() && out.size() <= max) {
    while (i < line.size() && space(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !space(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
}

// The meaning of 3 to 7 columns without a header.
const std::vector<PointField>& columns_without_header(std::size_t n) {
  using F = PointField;
  static const std::vector<PointField> layouts[5] = {
      {F::X, F::Y, F::Z},
      {F::X, F::Y, F::Z, F::Radius},
      {F::X, F::Y, F::Z, F::Radius, F::Temperature},
      {F::X, F::Y, F::Z, F::Red, F::Green, F::Blue},
      {F::X, F::Y, F::Z, F::Radius, F::Red, F::Green, F::Blue},
  };
  return layouts[n - 3];
}

}  // namespace

PointCloud parse_point_text(std::string_view text, const std::string& name) {
  auto fail = [&](const std::string& where, const std::string& what) -> void {
    throw InputError(name + ": " + where + ": " + what);
  };
  std::vector<std::string_view> cols;
  std::vector<std::string> shown;             // each column's name in messages
  std::vector<int> field_of;                  // each column's PointField
  std::size_t width = 0, layout_line = 0;     // columns of every row, and the line that set it
  bool header = false;
  PointFieldColumns fields;
  std::optional<PointCloudBuilder> cloud;
  std::array<double, kPointFieldCount> point{};

  std::size_t pos = 0, line = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    std::string_view raw = text.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
    pos = nl == std::string_view::npos ? text.size() : nl + 1;
    ++line;
    if (const std::size_t hash = raw.find('#'); hash != std::string_view::npos) raw = raw.substr(0, hash);
    const std::string_view content = trim(raw);
    if (content.empty()) continue;
    const auto at = [line] { return "line " + std::to_string(line); };  // only on an error

    if (!cloud) {  // the first line: a header, or the first point whose columns set the layout
      split(content, kPointFieldCount, cols);
      double v;
      if (!parse_number(cols[0], v)) {
        header = true;
        std::vector<std::string_view> names(cols.begin(), cols.end());
        if (names.size() > std::size_t(kPointFieldCount))
          fail(at(), "a header of more than " + std::to_string(kPointFieldCount) +
                       " columns: expected names among x y z radius temperature r g b vx vy vz");
        int unknown = -1;
        const std::string problem = resolve_point_fields(names, false, fields, &unknown);
        if (problem == "unknown") {
          std::vector<std::string> known;
          for (const auto& spellings : point_field_names()) known.insert(known.end(), spellings.begin(), spellings.end());
          fail(at() + ", column " + std::to_string(unknown + 1),
               "unknown column " + quote_token(names[std::size_t(unknown)]) + did_you_mean(names[std::size_t(unknown)], known) +
                   ": expected x, y, z, radius, temperature, r, g, b, vx, vy or vz (the first line names the columns "
                   "when it is not a point)");
        }
        if (!problem.empty()) fail(at() + " (the header)", problem);
        for (std::string_view n : names) shown.push_back(make_valid_utf8(shorten(n)));
        field_of.assign(names.size(), -1);
        for (int f = 0; f < kPointFieldCount; ++f)
          if (fields.has(PointField(f))) field_of[std::size_t(fields.column[std::size_t(f)])] = f;
        width = names.size();
        layout_line = line;
        cloud.emplace(fields);
        continue;
      }
      if (cols.size() < 3 || cols.size() > 7)
        fail(at(), std::to_string(cols.size()) + (cols.size() > 7 ? " or more" : "") +
                     " columns without a header: expected 3 (x y z), 4 (x y z radius), 5 (x y z radius temperature), "
                     "6 (x y z r g b) or 7 (x y z radius r g b), or a first line naming the columns");
      width = cols.size();
      layout_line = line;
      for (PointField f : columns_without_header(width)) {
        fields.column[std::size_t(f)] = int(field_of.size());
        field_of.push_back(int(f));
        shown.emplace_back(point_field_name(f));
      }
      cloud.emplace(fields);
    }

    split(content, width, cols);
    if (cols.size() != width)
      fail(at(), "expected " + std::to_string(width) + " columns (as " + (header ? "the header on line " : "line ") +
                   std::to_string(layout_line) + (header ? " names" : " has") + "), got " +
                   (cols.size() > width ? "more" : std::to_string(cols.size())));
    if (cloud->size() == kMaxCloudPoints)
      fail(at(), "more than " + std::to_string(kMaxCloudPoints) + " points: expected at most that many (the limit of a point cloud)");
    for (std::size_t c = 0; c < width; ++c) {
      double v;
      if (!parse_number(cols[c], v))
        fail(at() + ", column " + std::to_string(c + 1) + " (" + shown[c] + ")", "expected a number, got " + quote_token(cols[c]));
      point[std::size_t(field_of[c])] = v;
    }
    if (const int bad = cloud->add(point); bad >= 0) {
      const std::size_t c = std::size_t(fields.column[std::size_t(bad)]);
      fail(at() + ", column " + std::to_string(c + 1) + " (" + shown[c] + ")",
           std::string("expected ") + point_value_expected(PointField(bad), point[std::size_t(bad)]) + ", got " +
               quote_token(cols[c]));
    }
  }
  if (!cloud)
    throw InputError(name + ": no points and no header: expected lines of x y z (and optional columns), or a first "
                            "line naming the columns");
  return cloud->take();
}

}  // namespace draught
