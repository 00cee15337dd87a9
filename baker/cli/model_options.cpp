#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "baker/cli/commands.h"
#include "baker/custom/loader.h"
#include "kiln/table.h"

namespace kiln::cli {

void ModelParamOptions::Add(CLI::App* app) {
  oRoughness = app->add_option("--roughness,-r", roughness,
                               "roughness r (alpha = r^2 microfacet, sigma = r Oren-Nayar)");
  oRho = app->add_option("--rho", rho, "albedo rho");
  oF0 = app->add_option("--f0", f0, "Schlick F0 (specular) or the model's F0 (diffuse)");
  oEta = app->add_option("--eta", eta, "index of refraction (exact Fresnel)");
  oK = app->add_option("--k", k, "extinction coefficient (conductor Fresnel)");
  oRs = app->add_option("--rs", rs, "specular reflectance R_s");
  oNu = app->add_option("--nu", nu, "Ashikhmin-Shirley exponent along u");
  oNv = app->add_option("--nv", nv, "Ashikhmin-Shirley exponent along v");
}

ModelParams ModelParamOptions::Params() const {
  ModelParams p;
  auto set = [](CLI::Option* o, double v, std::optional<double>& out) {
    if (o && o->count()) out = v;
  };
  set(oRoughness, roughness, p.roughness);
  set(oRho, rho, p.rho);
  set(oF0, f0, p.f0);
  set(oEta, eta, p.eta);
  set(oK, k, p.k);
  set(oRs, rs, p.rs);
  set(oNu, nu, p.nu);
  set(oNv, nv, p.nv);
  return p;
}

void AddCustomModelOptions(CLI::App& app) {
  for (const char* command : {"eval", "integrate", "bake", "verify", "plan", "list"}) {
    CLI::App* sub = app.get_subcommand(command);
    // Loaded while the command line is parsed, before the command runs: its id is then known
    // to every lookup of the command (the model, --only, a scene's materials, a table's model).
    sub->add_option_function<std::vector<std::string>>(
           "--model-source",
           [](const std::vector<std::string>& paths) {
             for (const std::string& p : paths) LoadModelSource(p);
           },
           "a user's model: C++ source (kiln/model_abi.h), compiled into a cached library")
        ->type_name("FILE.cpp")
        ->allow_extra_args(false);  // one file each time: a scene path stays positional
    sub->add_option_function<std::vector<std::string>>(
           "--model-library",
           [](const std::vector<std::string>& paths) {
             for (const std::string& p : paths) LoadModelLibrary(p);
           },
           "a user's model: shared library built from a kiln/model_abi.h source")
        ->type_name("FILE.so")
        ->allow_extra_args(false);
  }
}

std::vector<std::string> UniqueNames(const std::string& list) {
  std::vector<std::string> names;
  std::set<std::string> seen;
  for (const std::string& name : splitList(list, ','))
    if (seen.insert(name).second) names.push_back(name);
  return names;
}

std::string FullPrecision(double x) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", x);
  return buf;
}

namespace {

/// True when `text` (after leading blanks, which CLI11's conversions skip) is a plain decimal
/// integer: an optional sign and digits, without leading zeros (CLI11 2.1 reads "010" as octal 8
/// and "0x10" as 16).
bool IsDecimalInteger(const std::string& text) {
  size_t i = text.find_first_not_of(" \t");
  if (i == std::string::npos) return false;
  if (text[i] == '+' || text[i] == '-') ++i;
  size_t digits = text.find_first_not_of("0123456789", i);
  if (digits != std::string::npos || i == text.size()) return false;
  return text[i] != '0' || i + 1 == text.size();
}

/// True when `text` is a plain decimal number: what IsDecimalInteger takes, with an optional
/// fraction and exponent ("-1.5e-3", ".5", "2."), or inf, infinity, nan in any case (the commands
/// refuse those with their own message). No hexadecimal ("0x10", "0x1p3").
bool IsDecimalNumber(const std::string& text) {
  size_t i = text.find_first_not_of(" \t");
  if (i == std::string::npos) return false;
  if (text[i] == '+' || text[i] == '-') ++i;
  std::string rest = text.substr(i);
  for (char& c : rest) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (rest == "inf" || rest == "infinity" || rest == "nan") return true;
  auto digitsAt = [&](size_t& at) {
    size_t start = at;
    while (at < rest.size() && std::isdigit(static_cast<unsigned char>(rest[at]))) ++at;
    return at - start;
  };
  size_t at = 0, mantissa = digitsAt(at);
  if (at < rest.size() && rest[at] == '.') mantissa += digitsAt(++at);
  if (mantissa == 0) return false;
  if (at < rest.size() && rest[at] == 'e') {
    ++at;
    if (at < rest.size() && (rest[at] == '+' || rest[at] == '-')) ++at;
    if (digitsAt(at) == 0) return false;
  }
  return at == rest.size();
}

/// "" when `text` is a plain decimal integer (integer) or number that CLI11 reads to the last
/// character, else the complaint.
std::string NumberProblem(const std::string& text, bool integer) {
  std::string wanted = integer ? "a decimal integer" : "a decimal number";
  if (text.empty()) return "needs " + wanted + ", got ''";
  bool decimal = integer ? IsDecimalInteger(text) : IsDecimalNumber(text);
  char* end = nullptr;
  if (integer)
    std::strtoll(text.c_str(), &end, 10);
  else
    std::strtod(text.c_str(), &end);
  if (!decimal || end != text.c_str() + text.size())
    return "needs " + wanted + ", got '" + text + "'";
  return "";
}

}  // namespace

void RefuseNonNumbers(CLI::App& app) {
  for (CLI::Option* o : app.get_options()) {
    std::string type = o->get_type_name();
    type = type.substr(0, type.find(':'));  // validators append ":DESCRIPTION"
    bool integer = type == "INT" || type == "UINT";
    if (!integer && type != "FLOAT") continue;
    o->check(
        CLI::Validator([integer](std::string& text) { return NumberProblem(text, integer); }, ""));
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) RefuseNonNumbers(*sub);
}

void CheckThreads(const std::string& command, int threads) {
  if (threads < 0 || threads > kMaxThreads)
    throw std::invalid_argument(command + ": -j " + std::to_string(threads) + " must be in [1, " +
                                std::to_string(kMaxThreads) + "]");
}

void CheckThreadOptions(CLI::App& app) {
  for (CLI::Option* o : app.get_options()) {
    if (o->get_name() != "--threads") continue;
    // More threads than the address space holds (ulimit -v) would abort in pthread_create:
    // a -j above ThreadLimit() runs ThreadLimit() threads, with a warning.
    o->transform(CLI::Validator(
        [](std::string& text) -> std::string {
          if (!IsDecimalInteger(text)) return "";  // refused by the checks below
          long long n = std::strtoll(text.c_str(), nullptr, 10);
          if (n >= 1 && n <= kMaxThreads)
            text = std::to_string(ThreadsToRun(static_cast<int>(n), ThreadLimit()));
          return "";
        },
        ""));
    // Only a -j the user gave is checked: the commands' own default 0 means all cores.
    o->check(CLI::Validator(
        [](std::string& text) -> std::string {
          char* end = nullptr;
          long long n = std::strtoll(text.c_str(), &end, 10);
          if (n >= 1 && n <= kMaxThreads) return "";
          return "-j " + text + " must be in [1, " + std::to_string(kMaxThreads) + "]";
        },
        ""));
  }
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
    CheckThreadOptions(*sub);
}

std::vector<std::string> NumbersAsPositionals(int argc, char** argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    // "-inf", "-nan", "-.5": CLI11 2.1 takes them for the short options -i, -n, -. (it only
    // knows numbers that start "-DIGIT"). A leading space keeps them numbers (strtod and CLI11's
    // conversions skip it) and out of CLI11's option syntax.
    if (a.size() > 1 && a[0] == '-' && !(a[1] >= '0' && a[1] <= '9') && a[1] != '-') {
      char* end = nullptr;
      std::strtod(a.c_str(), &end);
      if (end == a.c_str() + a.size()) a = " " + a;
    }
    args.push_back(a);
  }
  return args;
}

}  // namespace kiln::cli
