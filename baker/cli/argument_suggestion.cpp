// "Did you mean" for a mistyped subcommand or option (CLI11 2.1 has no suggestions).
#include <algorithm>

#include "baker/cli/commands.h"
#include "baker/util/did_you_mean.h"

namespace kiln::cli {
namespace {

/// Every spelling of the options of `app`: "--threads", "-j", ...
std::vector<std::string> OptionNames(const CLI::App& app) {
  std::vector<std::string> names;
  for (const CLI::Option* o : app.get_options()) {
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : o->get_snames()) names.push_back("-" + n);
  }
  return names;
}

bool IsOptionLike(const std::string& arg) {
  return arg.size() > 1 && arg[0] == '-' && !(arg[1] >= '0' && arg[1] <= '9') && arg[1] != '.';
}

}  // namespace

std::string SuggestArgument(CLI::App& app, const std::vector<std::string>& args) {
  std::vector<std::string> known = OptionNames(app);
  CLI::App* sub = nullptr;
  for (const std::string& arg : args) {
    if (arg == "--") break;
    if (IsOptionLike(arg)) {
      std::string name = arg.substr(0, arg.find('='));
      if (std::find(known.begin(), known.end(), name) != known.end()) continue;
      std::string best = DidYouMean(name, known);
      if (!best.empty()) return best;
      continue;
    }
    if (sub) continue;  // a value or positional argument of the subcommand
    // The first word is the subcommand.
    std::vector<std::string> subcommands;
    for (const CLI::App* s : app.get_subcommands([](CLI::App*) { return true; }))
      subcommands.push_back(s->get_name());
    if (std::find(subcommands.begin(), subcommands.end(), arg) == subcommands.end()) {
      return DidYouMean(arg, subcommands);
    }
    sub = app.get_subcommand(arg);
    std::vector<std::string> own = OptionNames(*sub);
    known.insert(known.end(), own.begin(), own.end());
  }
  return "";
}

}  // namespace kiln::cli
