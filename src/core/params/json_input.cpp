#include "core/params/json_input.hpp"

#include "core/io/files.hpp"
#include "core/text/echo.hpp"

#include <cstdint>
#include <vector>

namespace draught {

using nlohmann::json;

namespace {

// Appends the JSON text of j to out, stopping soon after out is longer than `limit`.
// Every level appends a byte before it descends, so the recursion is at most `limit`
// deep whatever the value's depth.
void dump_bounded(const json& j, std::string& out, std::size_t limit) {
  if (out.size() > limit) return;
  auto string_text = [&](const std::string& s) {  // only the part that can show
    const json part = std::string(utf8_prefix(s, limit - out.size() + 1));
    out += part.dump(-1, ' ', false, json::error_handler_t::replace);
  };
  if (j.is_object()) {
    out += '{';
    for (auto it = j.begin(); it != j.end() && out.size() <= limit; ++it) {
      if (it != j.begin()) out += ',';
      string_text(it.key());
      out += ':';
      dump_bounded(it.value(), out, limit);
    }
    out += '}';
  } else if (j.is_array()) {
    out += '[';
    for (auto it = j.begin(); it != j.end() && out.size() <= limit; ++it) {
      if (it != j.begin()) out += ',';
      dump_bounded(*it, out, limit);
    }
    out += ']';
  } else if (j.is_string()) {
    string_text(j.get_ref<const std::string&>());
  } else {
    out += j.dump();  // a number, true, false, null, or (never from a file) binary: short
  }
}

// Walks the document as the parser reads it (SAX: no values are built) and refuses it
// when it nests deeper than kMaxJsonDepth or has a key longer than kMaxJsonKeyBytes.
// Keeps the path of keys and array indices, so the error names the field.
class ShapeCheck {
 public:
  using number_integer_t = json::number_integer_t;
  using number_unsigned_t = json::number_unsigned_t;
  using number_float_t = json::number_float_t;
  using string_t = json::string_t;
  using binary_t = json::binary_t;

  explicit ShapeCheck(const std::string& file) : file_(file) {}

  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(number_integer_t) { return value(); }
  bool number_unsigned(number_unsigned_t) { return value(); }
  bool number_float(number_float_t, const string_t&) { return value(); }
  bool string(string_t&) { return value(); }
  bool binary(binary_t&) { return value(); }
  bool start_object(std::size_t) { return open(false); }
  bool start_array(std::size_t) { return open(true); }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool key(string_t& k) {
    if (k.size() > kMaxJsonKeyBytes)
      fail("a key of " + std::to_string(k.size()) + " bytes (" + quote_input(k) + "), longer than the limit of " +
           std::to_string(kMaxJsonKeyBytes) + " bytes for a field name", k);
    levels_.back().key = k;
    return true;
  }
  // Syntax errors are reported by the parse that follows, with line and column.
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }

 private:
  struct Level {
    bool array;
    std::size_t index = 0;
    std::string key;
  };

  bool value() {
    if (!levels_.empty() && levels_.back().array) ++levels_.back().index;
    return true;
  }
  bool open(bool array) {
    if (levels_.size() >= std::size_t(kMaxJsonDepth))
      fail("nested more than " + std::to_string(kMaxJsonDepth) + " levels deep (arrays and objects inside each "
           "other), the limit", "");
    levels_.push_back({array});
    return true;
  }
  bool close() {
    levels_.pop_back();
    return value();
  }
  // The field being read, named as the loaders name fields (params.liquid.fill,
  // actions[3].value) down to the deepest object: the arrays nested below it are what is
  // too deep. Runs of nested arrays show as "[i]..." and the whole name is capped, so a
  // deep document does not make a deep message.
  std::string path(const std::string& pending_key) const {
    std::size_t objects = 0;  // levels up to and including the deepest object
    for (std::size_t i = 0; i < levels_.size(); ++i)
      if (!levels_[i].array) objects = i + 1;
    std::string p;
    for (std::size_t i = 0; i < objects; ++i) {
      const Level& l = levels_[i];
      if (l.array) {
        if (i > 0 && levels_[i - 1].array) continue;
        const bool run = i + 1 < objects && levels_[i + 1].array;
        p += "[" + std::to_string(l.index) + "]" + (run ? "..." : "");
      } else {
        const std::string& k = i + 1 == levels_.size() && !pending_key.empty() ? pending_key : l.key;
        p += (p.empty() ? "" : ".") + shorten(k, 24);
      }
    }
    return shorten(p, 2 * kEchoBytes);
  }
  [[noreturn]] void fail(const std::string& what, const std::string& pending_key) const {
    const std::string field = path(pending_key);
    throw InputError(file_ + ": " + (field.empty() ? std::string() : "field '" + field + "': ") + what);
  }

  const std::string& file_;
  std::vector<Level> levels_;
};

// The parser quotes the token it last read, raw: it may be a whole long string, or hold
// bytes that are not UTF-8. Cap it and make it valid; keep the rest of the message.
std::string tidy_parser_message(const std::string& what) {
  const std::string marker = "last read: '";
  const auto a = what.find(marker);
  if (a == std::string::npos) return shorten(make_valid_utf8(what), 4 * kEchoBytes);
  const auto from = a + marker.size();
  auto to = what.find("'; expected", from);
  if (to == std::string::npos) to = what.ends_with("'") ? what.size() - 1 : what.size();
  // The end of the token is where the parser stopped: show that part.
  std::string token = make_valid_utf8(what.substr(from, to - from));
  if (token.size() > kEchoBytes) {
    std::size_t cut = token.size() - kEchoBytes;
    while (cut < token.size() && (static_cast<unsigned char>(token[cut]) & 0xC0) == 0x80) ++cut;  // whole characters
    token = "..." + token.substr(cut);
  }
  return make_valid_utf8(what.substr(0, from)) + token + shorten(make_valid_utf8(what.substr(to)), 2 * kEchoBytes);
}

}  // namespace

std::string short_dump(const json& j) {
  std::string s;
  dump_bounded(j, s, kEchoBytes);
  return s.size() <= kEchoBytes ? s : std::string(utf8_prefix(s, kEchoBytes - 3)) + "...";
}

ParamValue param_value_from_json(const ParamDesc& d, const json& j, const std::string& file, const std::string& field) {
  auto fail = [&]() -> ParamValue {
    throw InputError(file + ": field '" + field + "': expected " + expected_text(d) + ", got " + short_dump(j));
  };
  auto num3 = [&](const json& a, glm::vec3& out) {
    if (!a.is_array() || a.size() != 3) return false;
    for (int i = 0; i < 3; ++i) {
      if (!a[size_t(i)].is_number()) return false;
      out[i] = a[size_t(i)].get<float>();
    }
    return true;
  };
  ParamValue v;
  switch (d.type) {
    case ParamType::Float:
      if (!j.is_number()) return fail();
      v = j.get<float>();
      break;
    case ParamType::Int: {
      if (!j.is_number_integer()) return fail();
      const auto wide = j.get<std::int64_t>();  // range-checked before narrowing
      if (wide < std::int64_t(d.min) || wide > std::int64_t(d.max)) return fail();
      v = int(wide);
      break;
    }
    case ParamType::Bool:
      if (!j.is_boolean()) return fail();
      v = j.get<bool>();
      break;
    case ParamType::Vec3:
    case ParamType::Color: {
      glm::vec3 c;
      if (!num3(j, c)) return fail();
      v = c;
      break;
    }
    case ParamType::Enum:
      if (!j.is_string()) return fail();
      v = j.get<std::string>();
      break;
    case ParamType::Curve: {
      if (!j.is_array()) return fail();
      Curve c;
      for (auto& pt : j) {
        if (!pt.is_array() || pt.size() != 2 || !pt[0].is_number() || !pt[1].is_number()) return fail();
        c.push_back({pt[0].get<float>(), pt[1].get<float>()});
      }
      v = c;
      break;
    }
    case ParamType::File:
      if (!j.is_string()) return fail();
      v = j.get<std::string>();
      break;
  }
  try {
    validate_value(d, v);
  } catch (const ParamError& e) {
    throw InputError(file + ": field '" + field + "': expected " + e.expected + ", got " + short_dump(j));
  }
  return v;
}

json parse_json_file_text(const std::string& text, const std::string& file) {
  ShapeCheck shape(file);
  json::sax_parse(text, &shape);  // throws InputError for a document too deep to handle
  json j;
  try {
    j = json::parse(text);
  } catch (const json::parse_error& e) {
    size_t line = 1, col = 1;
    for (size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') ++line, col = 1;
      else ++col;
    }
    std::string what = e.what();
    auto p = what.find(": ", what.find("parse error"));
    // The parser quotes what it last read, raw: a long token, or invalid UTF-8.
    throw InputError(file + ":" + std::to_string(line) + ":" + std::to_string(col) + ": malformed JSON: " +
                     tidy_parser_message(p == std::string::npos ? what : what.substr(p + 2)));
  } catch (const json::exception& e) {  // e.g. a number too large for a double
    std::string what = e.what();
    auto p = what.find("] ");
    throw InputError(file + ": malformed JSON: " +
                     shorten(make_valid_utf8(p == std::string::npos ? what : what.substr(p + 2)), 4 * kEchoBytes));
  }
  return j;
}

}  // namespace draught
