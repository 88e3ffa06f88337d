#pragma once
// Checks that run while the command line is parsed, so a bad option fails
// in one line before any data is loaded or any work starts.

#include "core/io/replaceable_output.h"
#include "core/support/errors.h"
#include "core/support/input_limits.h"
#include "core/support/option_range.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <optional>
#include <string>

namespace triwalk {

// Numbers >= 0 (or > 0), with a message that names the bound plainly
// (CLI11's own says "not in range 0 to 1.8e308").
CLI::Validator nonNegativeNumber();
CLI::Validator positiveNumber();
// The values an option shares with a selection file's settings.
CLI::Validator within(OptionRange range);
// A position coordinate in metres, within kMaxCoordinateMetres of the origin.
CLI::Validator coordinate();
// The lattices --error-stride offers (decimate, suite, view, bench): every
// pixel, every other row and column, every fourth.
CLI::Validator errorStride();
// An output file: its folder exists and is writable, it is not a folder,
// and it is absent, empty or an earlier output of this kind (another
// command's output or a user's file is never overwritten).
CLI::Validator writableFile(OutputKind kind);
// The same, said by the command itself (a side output may lie inside the
// command's output folder, which does not exist yet): InputError naming the option.
void checkWritableFile(const std::string& file, const std::string& option, OutputKind kind);
// file's path inside folder when it lies in it (written lexically: "a/b"
// in "a"), else nothing.
std::optional<std::filesystem::path> pathInside(const std::string& file, const std::string& folder);
// An output folder: it is a writable folder, or it can be created in the
// nearest folder above it that exists.
CLI::Validator writableDirectory();
// --tiles: auto, off or a number of tiles (parseTileCount).
CLI::Validator tileCount();

// Runs work; an InputError it throws about a setting of the core (named as
// in a selection file, "error_width") is said about the option that sets
// it ("--error-width"): the core names settings, the command line its flags.
template <class Work>
auto namingOption(const std::string& setting, const std::string& option, Work&& work) {
  try {
    return work();
  } catch (const InputError& error) {
    if (error.subject() != setting) throw;
    throw InputError(option, error.problem());
  }
}

// Hides the options that tune the method rather than use it (warp, blend
// and error constants, the decimator's alternative rules) from --help;
// --help-all lists them with the rest. They work the same either way.
void hideExpertOptions(CLI::App& app);

// Gives every floating-point option of every command a check that refuses
// NaN and infinities (CLI11's range checks let NaN through), and makes
// parse errors one line.
void hardenCommandLine(CLI::App& app);

}  // namespace triwalk
