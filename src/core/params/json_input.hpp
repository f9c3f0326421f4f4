// Reading JSON input files (presets, timelines) with errors that name the file, the
// field and what was expected.
#pragma once

#include "core/params/params.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>

namespace draught {

// Limits on the shape of an input file, checked before the document is built: nothing
// valid comes near them, and past them the recursive code that handles JSON values (the
// library's dump and comparisons, error messages) could overflow the stack.
inline constexpr int kMaxJsonDepth = 256;          // arrays and objects inside each other
inline constexpr std::size_t kMaxJsonKeyBytes = 128;  // an object key (a field name)

// Parses text; a syntax error becomes InputError "file:line:col: malformed JSON: ...",
// nesting deeper than kMaxJsonDepth or a key longer than kMaxJsonKeyBytes an InputError
// "file: field 'a.b[3]': ..." naming where it happens.
nlohmann::json parse_json_file_text(const std::string& text, const std::string& file);
// A JSON value as a parameter of the table; InputError "file: field 'FIELD': expected ...".
ParamValue param_value_from_json(const ParamDesc&, const nlohmann::json&, const std::string& file,
                                 const std::string& field);
// The JSON text of a value for error messages: at most kEchoBytes bytes and "..."
// (never a cut UTF-8 character), built without serialising more than that, so a huge or
// deeply nested value costs nothing.
std::string short_dump(const nlohmann::json&);

}  // namespace draught
