// Command-line errors as the README promises them: "draught: error: " + the flag, the
// value and what was expected, the nearest valid word for a typo, exit code 1. CLI11
// only splits the command line here; values are converted and checked by these
// functions, so every message has the same form.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace draught::cli {

// An unknown verb, caught before CLI11 (which would answer "A subcommand is required"):
// throws InputError "unknown command 'rendr' (did you mean 'render'?); expected ...".
void check_verb(const CLI::App&, int argc, const char* const* argv);

// What a CLI11 parse error means to a user, without the "draught: error: " prefix.
std::string explain_parse_error(const CLI::App&, const CLI::ParseError&);
// The same for words left over after a parse (allow_extras): an unknown flag, with the
// nearest valid one, or a stray argument.
std::string explain_extras(const CLI::App&);

// A finite number in [lo, hi] ("nan", "inf", "30fps" and "" are refused); throws
// InputError "--fps nan: expected a number from 1 to 120 (frames per second)".
double number_flag(const std::string& flag, const std::string& text, double lo, double hi, const char* unit);
// A whole number in [lo, hi].
int integer_flag(const std::string& flag, const std::string& text, int lo, int hi);
// A comma-separated list of whole numbers, each in [lo, hi].
std::vector<int> integer_list_flag(const std::string& flag, const std::string& text, int lo, int hi);
// One of `choices`, or InputError naming them and the nearest.
std::string choice_flag(const std::string& flag, const std::string& text, const std::vector<std::string>& choices);

// DRAUGHT_DEVICE, when set, is one of software, hardware, auto.
void check_device_environment();

}  // namespace draught::cli
