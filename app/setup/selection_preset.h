#pragma once
// --preset: a named starting point for every setting of a selection, so a
// user picks a recipe instead of a dozen knobs. Options given beside it
// override its values one by one.

#include <CLI/CLI.hpp>

#include <string>

namespace triwalk {

struct DecimationArguments;
struct ErrorArguments;
struct SelectionArguments;

// The presets, by the name --preset takes:
//   default  triwalk's measured best (docs/DESIGN.md);
//   paper    the paper's own rules, to reproduce its Table 1: the centroid
//            collapse cost, unweighted, the hull kept, no refinement,
//            inverse-distance weights, raw holes, uniform pixel weights,
//            and its absolute threshold 1.85 when no stopping option is
//            given (the warp stays the mesh warp: selection_preset.cpp);
//   fast     the selection's errors on every other row and column of the
//            error panorama (--error-stride 2), measured cheaper.
// Registers --preset on command. Added before the options it sets: CLI11
// runs option callbacks in the order the options were added, so the
// preset's values land first and explicit options replace them.
void addPresetOption(CLI::App& command, DecimationArguments& arguments);

// Sets arguments to the preset's values; InputError for an unknown name.
void applyPreset(const std::string& name, DecimationArguments& arguments);
// The two halves of a preset apart, for the suite, whose selections take
// a preset while its evaluation stays the same: how references are
// selected (InputError for an unknown name), and the errors they are
// selected with (the paper's weights, holes, pixel weights and error
// destinations; nothing for the others).
void applySelectionPreset(const std::string& name, SelectionArguments& selection);
void applyPresetErrorRules(const std::string& name, ErrorArguments& errors);

}  // namespace triwalk
