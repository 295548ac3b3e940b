// The ui registry: each algorithm family's window side (panel, overlay, view
// flags), keyed by the family's id in the culling registry
// (culling/registry/registry.h). Families without an entry (the baselines, the
// oracle) show the shared panels only. Adding a family: one line in
// family_views.cpp (docs/ARCHITECTURE.md, "Adding a family").
#pragma once
#include <string>
#include <string_view>
#include <vector>

#include "ui/family_view.h"

namespace gridcull {

// Every family's view, in registry order; pointers into it stay valid until the
// next registerFamilyView or unregisterFamilyView.
const std::vector<FamilyViewEntry>& familyViews();
// The entry of family `family` (a FamilyEntry::id), or nullptr.
const FamilyViewEntry* findFamilyView(std::string_view family);
// The entry of the family of algorithm `algorithm`, or nullptr.
const FamilyViewEntry* familyViewOfAlgorithm(std::string_view algorithm);

// Adds an entry (tests add a test-only family's). False with `error` when the
// family has one already, is not in the culling registry, or a flag is taken
// (by another view or by a knob).
bool registerFamilyView(FamilyViewEntry entry, std::string& error);
void unregisterFamilyView(const std::string& family);

// Checks every view flag set in `flags` against `scene` with its family's view,
// whichever family is selected, so a bad one is reported before the window
// opens. False with `error` naming the flag.
bool checkViewFlags(const KnobValues& flags, const Scene& scene, std::string& error);

// Every view flag, in registry order, the one with `flag`, and its entry.
std::vector<const Knob*> allViewFlags();
const Knob* findViewFlag(std::string_view flag);
const FamilyViewEntry* familyViewOfFlag(std::string_view flag);

}  // namespace gridcull
