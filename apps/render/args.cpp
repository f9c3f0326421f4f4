#include "args.hpp"

#include "core/io/files.hpp"
#include "core/text/echo.hpp"
#include "core/text/suggest.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace draught::cli {

namespace {

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string join_words(const std::vector<std::string>& words, const char* last_sep) {
  std::string s;
  for (size_t i = 0; i < words.size(); ++i) s += (i == 0 ? "" : i + 1 == words.size() ? last_sep : ", ") + words[i];
  return s;
}

std::vector<std::string> verbs(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; }))
    names.push_back(sub->get_name());
  return names;
}

// Every spelling of every flag of `app` ("--fps", "-o", "--output", ...).
std::vector<std::string> flag_names(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (auto& l : o->get_lnames()) names.push_back("--" + l);
    for (auto& s : o->get_snames()) names.push_back("-" + s);
  }
  return names;
}

// "draught render", or "draught" when no verb was parsed.
const CLI::App& command_of(const CLI::App& app) {
  auto subs = app.get_subcommands();
  return subs.empty() ? app : *subs.front();
}

std::string command_name(const CLI::App& app, const CLI::App& cmd) {
  return &cmd == &app ? "draught" : "draught " + cmd.get_name();
}

}  // namespace

void check_verb(const CLI::App& app, int argc, const char* const* argv) {
  // The global flags take no values, so the first word that is not a flag is the verb.
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.starts_with("-")) continue;
    const auto names = verbs(app);
    if (std::find(names.begin(), names.end(), word) != names.end()) return;
    throw InputError("unknown command " + quote_input(word) + did_you_mean(word, names) + "; expected " +
                     join_words(names, " or ") + " (`draught --help` says more)");
  }
}

std::string explain_extras(const CLI::App& app) {
  const CLI::App& cmd = command_of(app);
  const std::string name = command_name(app, cmd);
  const std::string help = "; `" + name + " --help` lists " + (&cmd == &app ? "the commands" : "its flags");
  const auto extra = app.remaining(true);
  // A flag among the extras is the culprit (the words after it are its values).
  for (const std::string& word : extra) {
    if (!word.starts_with("-")) continue;
    const std::string flag = word.substr(0, word.find('='));
    return "unknown flag " + quote_input(flag) + " for `" + name + "`" + did_you_mean(flag, flag_names(cmd)) + help;
  }
  if (extra.empty()) return "unexpected arguments" + help;
  return "unexpected argument " + quote_input(extra.front()) + " for `" + name + "`" + help;
}

std::string explain_parse_error(const CLI::App& app, const CLI::ParseError& e) {
  const CLI::App& cmd = command_of(app);
  const std::string name = command_name(app, cmd);
  const std::string help = "; `" + name + " --help` lists " + (&cmd == &app ? "the commands" : "its flags");
  const std::string kind = e.get_name();
  if (kind == "ExtrasError" || (kind == "RequiredError" && &cmd == &app && app.remaining_size(true) > 0))
    return explain_extras(app);
  if (kind == "RequiredError") {
    if (&cmd == &app) return "expected a command: " + join_words(verbs(app), " or ") + " (`draught --help` says more)";
    if (cmd.get_name() == "validate")
      return "validate: expected one or more preset or timeline files, e.g. draught validate my-drink.json";
  }
  if (kind == "ArgumentMismatch") {
    // "--fps: 1 required FLOAT missing": name the flag and what its value is.
    const std::string what = e.what();
    const std::string flag = what.substr(0, what.find(':'));
    for (const CLI::Option* o : cmd.get_options())
      for (auto& l : o->get_lnames())
        if ("--" + l == flag || (!o->get_snames().empty() && "-" + o->get_snames().front() == flag))
          return flag + ": expected a value after it (" + o->get_description() + ")" + help;
    return flag + ": expected a value after it" + help;
  }
  return std::string(e.what()) + help;
}

double number_flag(const std::string& flag, const std::string& text, double lo, double hi, const char* unit) {
  double v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v) || v < lo || v > hi)
    throw InputError(flag + " " + shorten(text) + ": expected a number from " + fmt(lo) + " to " + fmt(hi) + " (" +
                     unit + ")");
  return v;
}

int integer_flag(const std::string& flag, const std::string& text, int lo, int hi) {
  int v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || v < lo || v > hi)
    throw InputError(flag + " " + shorten(text) + ": expected a whole number from " + std::to_string(lo) + " to " +
                     std::to_string(hi));
  return v;
}

std::vector<int> integer_list_flag(const std::string& flag, const std::string& text, int lo, int hi) {
  std::vector<int> out;
  for (size_t start = 0; start <= text.size();) {
    size_t end = text.find(',', start);
    if (end == std::string::npos) end = text.size();
    int v = 0;
    const std::string item = text.substr(start, end - start);
    auto [p, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
    if (item.empty() || ec != std::errc() || p != item.data() + item.size() || v < lo || v > hi)
      throw InputError(flag + " " + shorten(text) + ": expected whole numbers from " + std::to_string(lo) + " to " +
                       std::to_string(hi) + " separated by commas, e.g. 256,512; got " + quote_input(item));
    out.push_back(v);
    start = end + 1;
  }
  return out;
}

std::string choice_flag(const std::string& flag, const std::string& text, const std::vector<std::string>& choices) {
  if (std::find(choices.begin(), choices.end(), text) != choices.end()) return text;
  throw InputError(flag + " " + shorten(text) + ": expected " + join_words(choices, " or ") +
                   did_you_mean(text, choices));
}

void check_device_environment() {
  const char* env = std::getenv("DRAUGHT_DEVICE");
  if (!env || !*env) return;
  const std::string v = env;
  const std::vector<std::string> valid = {"software", "hardware", "auto"};
  if (std::find(valid.begin(), valid.end(), v) == valid.end())
    throw InputError("DRAUGHT_DEVICE=" + shorten(v) + ": expected software, hardware or auto" + did_you_mean(v, valid) +
                     " (or leave it unset)");
}

}  // namespace draught::cli
