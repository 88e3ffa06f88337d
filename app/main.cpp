// triwalk: image-based walkthroughs from triangulated RGB-D panoramas.
// Thin main: parse the command line, run the chosen subcommand, turn
// failures into one line on stderr and a non-zero exit status.

#include "app/commands/commands.h"
#include "app/setup/option_checks.h"
#include "core/support/errors.h"
#include "render/gl/gl_context.h"

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <string_view>

int main(int argc, char** argv) {
  // Decimation allocates and frees a few hundred kilobytes per warp, tens of
  // thousands of times; glibc would serve each from fresh zeroed pages
  // (mmap, then trimmed back): 7% of its profile in page faults, and the
  // first 150 collapses run 25% faster with the buffers kept in the heap
  // (docs/history/BENCHMARKS-2026-11.md, "Where the decimation's time goes").
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  CLI::App app{"triwalk: select reference panoramas by edge-collapse decimation and walk through them"};
  app.require_subcommand(1);
  // Before the subcommands, which inherit it.
  app.set_help_all_flag("--help-all", "Print this help with every option, those that tune the method too");
  triwalk::registerCaptureCommand(app);
  triwalk::registerImportCommand(app);
  triwalk::registerExportCommand(app);
  triwalk::registerExportPngCommand(app);
  triwalk::registerRegionCommand(app);
  triwalk::registerSynthCommand(app);
  triwalk::registerDecimateCommand(app);
  triwalk::registerTilesCommand(app);
  triwalk::registerEvalCommand(app);
  triwalk::registerRenderCommand(app);
  triwalk::registerSuiteCommand(app);
#ifdef TRIWALK_WITH_VIEWER
  triwalk::registerViewCommand(app);
#endif
  triwalk::registerBenchCommand(app);
  if (std::none_of(argv, argv + argc, [](const char* argument) { return std::string_view(argument) == "--help-all"; })) {
    triwalk::hideExpertOptions(app);
  }
  triwalk::hardenCommandLine(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  } catch (const triwalk::InputError& error) {
    std::fprintf(stderr, "triwalk: error: %s\n", triwalk::printableLine(error.what()).c_str());
    return 1;
  } catch (const triwalk::Interrupted&) {
    std::fprintf(stderr, "triwalk: interrupted; no output written\n");
    return 130;
  } catch (const triwalk::GlUnavailable& error) {
    std::fprintf(stderr, "triwalk: error: OpenGL: %s\n", triwalk::printableLine(error.what()).c_str());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "triwalk: error: %s\n", triwalk::printableLine(error.what()).c_str());
    return 1;
  }
  return 0;
}
