#include "app/setup/option_checks.h"

#include "app/setup/tile_jobs.h"

#include "core/support/errors.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <string>

namespace triwalk {

namespace {

std::optional<double> numberIn(const std::string& text) {
  // strtod, not from_chars: it reads "nan" and "inf" in any case, as CLI11 does.
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size()) return std::nullopt;
  return value;
}

bool isWritableDirectory(const std::filesystem::path& path) {
  std::error_code error;
  return std::filesystem::is_directory(path, error) && ::access(path.c_str(), W_OK | X_OK) == 0;
}

std::filesystem::path folderOf(const std::filesystem::path& path) {
  const std::filesystem::path parent = path.parent_path();
  return parent.empty() ? std::filesystem::path(".") : parent;
}

void visit(CLI::App& app, const CLI::Validator& finite) {
  for (CLI::Option* option : app.get_options()) {
    if (option->get_type_name().find("FLOAT") != std::string::npos) option->check(finite);
  }
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) visit(*command, finite);
}

}  // namespace

CLI::Validator nonNegativeNumber() {
  return CLI::Validator(
      [](std::string& text) {
        const std::optional<double> value = numberIn(text);
        // NaN and infinities are left to hardenCommandLine's finite check.
        return value && std::isfinite(*value) && *value < 0.0 ? "must not be negative, got " + text : std::string();
      },
      "NONNEGATIVE");
}

CLI::Validator positiveNumber() {
  return CLI::Validator(
      [](std::string& text) {
        const std::optional<double> value = numberIn(text);
        return value && std::isfinite(*value) && !(*value > 0.0) ? "must be positive, got " + text : std::string();
      },
      "POSITIVE");
}

CLI::Validator within(OptionRange range) {
  return CLI::Validator(
      [range](std::string& text) {
        const std::optional<double> value = numberIn(text);
        if (!value || !std::isfinite(*value) || range.contains(*value)) return std::string();
        char bounds[64];
        std::snprintf(bounds, sizeof bounds, "must be from %g to %g", double(range.lowest), double(range.highest));
        return std::string(bounds) + ", got " + text;
      },
      "RANGE");
}

CLI::Validator coordinate() {
  return CLI::Validator(
      [](std::string& text) {
        const std::optional<double> value = numberIn(text);
        return value && std::isfinite(*value) && !withinCoordinateBound(*value)
                   ? "must be within " + std::string(kCoordinateBoundText) + " of the origin, got " + text
                   : std::string();
      },
      "METRES");
}

CLI::Validator errorStride() { return CLI::IsMember({1, 2, 4}); }

namespace {

// What is wrong with writing this file, or nothing.
std::string writableFileProblem(const std::string& text, OutputKind kind) {
  const std::filesystem::path path(text);
  std::error_code error;
  if (text.empty()) return "empty file name";
  if (std::filesystem::is_directory(path, error)) return text + " is a folder, not a file";
  if (!isWritableDirectory(folderOf(path))) return "cannot write " + text + ": no writable folder " + folderOf(path).string();
  return foreignOutputProblem(path, kind);
}

}  // namespace

CLI::Validator writableFile(OutputKind kind) {
  return CLI::Validator([kind](std::string& text) { return writableFileProblem(text, kind); }, "FILE");
}

void checkWritableFile(const std::string& file, const std::string& option, OutputKind kind) {
  if (const std::string problem = writableFileProblem(file, kind); !problem.empty()) throw InputError(option, problem);
}

std::optional<std::filesystem::path> pathInside(const std::string& file, const std::string& folder) {
  if (file.empty() || folder.empty()) return std::nullopt;
  const std::filesystem::path relative =
      std::filesystem::path(file).lexically_normal().lexically_relative(std::filesystem::path(folder).lexically_normal());
  if (relative.empty() || relative.is_absolute() || *relative.begin() == ".." || *relative.begin() == ".") return std::nullopt;
  return relative;
}

CLI::Validator tileCount() {
  return CLI::Validator(
      [](std::string& value) -> std::string {
        if (value == "auto" || value == "off" || parseTileCount(value)) return {};
        return "must be auto, off or a number of tiles from 1 to 100000, got '" + value + "'";
      },
      "auto|off|N");
}

CLI::Validator writableDirectory() {
  return CLI::Validator(
      [](std::string& text) {
        if (text.empty()) return std::string("empty folder name");
        std::filesystem::path existing = std::filesystem::absolute(text).lexically_normal();
        std::error_code error;
        while (!std::filesystem::exists(existing, error) && existing.has_relative_path()) existing = existing.parent_path();
        if (!std::filesystem::is_directory(existing, error)) return "cannot create folder " + text + ": " + existing.string() + " is not a folder";
        if (!isWritableDirectory(existing)) return "cannot write in " + existing.string();
        return std::string();
      },
      "DIR");
}

namespace {

// Everything else is what a user of the command needs: its inputs and
// outputs, the quality target, --holes, --blend-weights, --source-mesh,
// the error width and --error-stride, the refinement radius.
const std::set<std::string> kExpertOptions = {
    "--stretch-test", "--grazing-angle", "--depth-ratio", "--point-warp",   "--mesh-tolerance",  "--epsilon",
    "--min-weight-distance", "--alpha",  "--beta",        "--delta",        "--pixel-weighting", "--triangle-destinations",
    "--cost",         "--fixed-boundary", "--one-ring",   "--unweighted-cost", "--priced-samples", "--recosting",
    "--exchanges",    "--refine-screen", "--refine-priced",
    // the suite's: select with other errors than it evaluates with
    "--selection-blend-weights", "--selection-source-mesh", "--selection-error-width"};

// --help without the expert options. They are left out of the listing,
// not hidden in CLI11's way (an empty group), which would also drop
// their names from CLI11's own error messages.
class EverydayFormatter : public CLI::Formatter {
public:
  std::string make_group(std::string group, bool isPositional, std::vector<const CLI::Option*> options) const override {
    std::erase_if(options, [](const CLI::Option* option) { return kExpertOptions.count(option->get_name(false, true)) > 0; });
    return options.empty() ? std::string() : CLI::Formatter::make_group(std::move(group), isPositional, std::move(options));
  }
};

void hideIn(CLI::App& command, const std::shared_ptr<CLI::Formatter>& formatter) {
  command.formatter(formatter);
  const std::vector<CLI::Option*> options = command.get_options();
  if (std::any_of(options.begin(), options.end(),
                  [](const CLI::Option* option) { return kExpertOptions.count(option->get_name(false, true)) > 0; })) {
    const std::string hint = "Options that tune the method (warp, blend and error constants, other collapse rules): --help-all";
    const std::string own = command.get_footer();  // a command's own footer (view's controls) stays first
    command.footer(own.empty() ? hint : own + "\n" + hint);
  }
  for (CLI::App* subcommand : command.get_subcommands([](CLI::App*) { return true; })) hideIn(*subcommand, formatter);
}

}  // namespace

void hideExpertOptions(CLI::App& app) { hideIn(app, std::make_shared<EverydayFormatter>()); }

void hardenCommandLine(CLI::App& app) {
  const CLI::Validator finite(
      [](std::string& text) {
        const std::optional<double> value = numberIn(text);
        return value && !std::isfinite(*value) ? "must be a finite number, got " + text : std::string();
      },
      "");
  visit(app, finite);
  app.failure_message([](const CLI::App*, const CLI::Error& error) { return "triwalk: error: " + printableLine(error.what()) + " (see --help)\n"; });
}

}  // namespace triwalk
