// The variants of the reference a student's engine may be: the lecture's three methods, each with
// one of the Tips slides' mistakes, the other resolve ("without Newton") or another integrator;
// then two mistakes at once. What each change means is said once, in the lecture's words with its
// slide (the table in variants.cpp).
#pragma once

#include "world.h"

#include <string>
#include <vector>

// One setting changed from the reference (or the method).
enum class ChangeKind { Method, Mistake, Resolve, Integrator };
struct Change {
    ChangeKind kind = ChangeKind::Method;
    int value = 0; // the enum's value (Method, Mistake, Resolve, Integrator)
};

struct Variant {
    WorldSettings settings;
    std::vector<Change> changes; // from the reference; empty for the reference itself
};

// "turn-based + move-back"; "the reference" when nothing changed.
std::string variantName(const std::vector<Change>& changes);
// "method turn-based", "mistake move-back", "resolve reflect", "integrator exact".
std::string changeName(const Change& change);
// What the change does to a student's blocks, in the lecture's words ("your blocks are pushed
// back along one axis instead of being put at the point of impact"), and the slide that says so.
std::string changeSays(const Change& change);
std::string changeSlide(const Change& change);

// The reference's variants, simplest first: each method alone, then with one change of a
// mistake, the resolve or the integrator. With `pairs`, also each method with two mistakes.
std::vector<Variant> variantsOf(const WorldSettings& reference, bool pairs);
