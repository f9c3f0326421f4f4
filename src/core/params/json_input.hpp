// Reading JSON input files (presets, timelines) with errors that name the file, the
// field and what was expected.
#pragma once

#include "core/params/params.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace draught {

// Parses text; a syntax error becomes InputError "file:line:col: malformed JSON: ...".
nlohmann::json parse_json_file_text(const std::string& text, const std::string& file);
// A JSON value as a parameter of the table; InputError "file: field 'FIELD': expected ...".
ParamValue param_value_from_json(const ParamDesc&, const nlohmann::json&, const std::string& file,
                                 const std::string& field);
// The JSON text of a value, cut to 60 characters for error messages.
std::string short_dump(const nlohmann::json&);

}  // namespace draught
