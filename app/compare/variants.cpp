#include "variants.h"

#include <iterator>

namespace {

// What each value of each setting does to a student's blocks, in the lecture's words, and the
// slide (lecture 3) that says so. One row per value; mistakes' slides are the engine's
// (mistakeSlide), so the panel, the stability matrix and this report name the same slide.
struct Meaning {
    ChangeKind kind;
    int value;
    const char* says;
    const char* slide; // nullptr: the engine's mistakeSlide()
};

constexpr Meaning kMeanings[] = {
    {ChangeKind::Method, static_cast<int>(Method::Perfect),
     "your engine moves every block to the earliest collision, resolves it and goes on with the "
     "rest of the frame",
     "Perfect Simulation"},
    {ChangeKind::Method, static_cast<int>(Method::MoveAndCorrect),
     "your engine moves every block the whole frame, then pushes overlapping blocks apart and "
     "resolves (\"just do it, clean up mess later\")",
     "Move & Correct Method"},
    {ChangeKind::Method, static_cast<int>(Method::TurnBased),
     "your engine moves the blocks one by one until their first collision, the others held "
     "still; a block that bounces loses the rest of its frame",
     "Turn-based Simulation"},
    {ChangeKind::Mistake, static_cast<int>(Mistake::Discrete),
     "your engine checks for overlap at the new position only, so a fast block passes through "
     "what it should hit (tunnelling)",
     nullptr},
    {ChangeKind::Mistake, static_cast<int>(Mistake::MoveBack),
     "your blocks are pushed back along one axis instead of being put at the point of impact "
     "POI = oldPosition + t·velocity, t = a/b",
     nullptr},
    {ChangeKind::Mistake, static_cast<int>(Mistake::FirstFound),
     "your engine resolves the first collision it finds in its list, not the earliest one of the "
     "frame (\"find the first one, and only resolve that one!\")",
     nullptr},
    {ChangeKind::Mistake, static_cast<int>(Mistake::NoApproachTest),
     "your engine also resolves blocks that already move apart: it does not check that the "
     "relative velocity along the axis closes",
     nullptr},
    {ChangeKind::Resolve, static_cast<int>(Resolve::Momentum),
     "your engine uses the momentum formula u = (m1·v1 + m2·v2)/(m1 + m2), v' = u - C·(v - u)",
     "Collisions on a Line - Full Formula"},
    {ChangeKind::Resolve, static_cast<int>(Resolve::Reflect),
     "your blocks each reverse their own velocity, v' = -C·v, as off a wall: without Newton, "
     "momentum is not kept when two moving blocks meet",
     "Demo: bouncing squares; with/without Newton"},
    {ChangeKind::Integrator, static_cast<int>(Integrator::SemiImplicitEuler),
     "your engine adds the acceleration to the velocity, then the velocity to the position",
     "Integration (semi-implicit Euler)"},
    {ChangeKind::Integrator, static_cast<int>(Integrator::ExplicitEuler),
     "your engine moves with the velocity from before the acceleration was added (explicit "
     "Euler), so a falling block lags the lecture's by g·dt² each frame",
     "Integration (semi-implicit Euler: velocity first, then position)"},
    {ChangeKind::Integrator, static_cast<int>(Integrator::Exact),
     "your engine follows the exact parabola, not the lecture's piecewise linear steps",
     "Integration: \"Piecewise linear instead of parabola\""},
};

const Meaning* meaningOf(const Change& c) {
    for (const Meaning& m : kMeanings)
        if (m.kind == c.kind && m.value == c.value) return &m;
    return nullptr;
}

void apply(WorldSettings& s, const Change& c) {
    switch (c.kind) {
    case ChangeKind::Method:
        s.method = static_cast<Method>(c.value);
        break;
    case ChangeKind::Mistake:
        s.set(static_cast<Mistake>(c.value), true);
        break;
    case ChangeKind::Resolve:
        s.resolve = static_cast<Resolve>(c.value);
        break;
    case ChangeKind::Integrator:
        s.integrator = static_cast<Integrator>(c.value);
        break;
    }
}

} // namespace

std::string changeName(const Change& c) {
    switch (c.kind) {
    case ChangeKind::Method:
        return std::string("method ") + methodName(static_cast<Method>(c.value));
    case ChangeKind::Mistake:
        return std::string("mistake ") + mistakeName(static_cast<Mistake>(c.value));
    case ChangeKind::Resolve:
        return std::string("resolve ") + resolveName(static_cast<Resolve>(c.value));
    case ChangeKind::Integrator:
        return std::string("integrator ") + integratorName(static_cast<Integrator>(c.value));
    }
    return "";
}

std::string variantName(const std::vector<Change>& changes) {
    if (changes.empty()) return "the reference";
    std::string name;
    for (const Change& c : changes) {
        if (!name.empty()) name += " + ";
        name += changeName(c);
    }
    return name;
}

std::string changeSays(const Change& c) {
    const Meaning* m = meaningOf(c);
    return m ? m->says : "";
}

std::string changeSlide(const Change& c) {
    const Meaning* m = meaningOf(c);
    if (m && m->slide) return m->slide;
    if (c.kind == ChangeKind::Mistake) return mistakeSlide(static_cast<Mistake>(c.value));
    return "";
}

std::vector<Variant> variantsOf(const WorldSettings& reference, bool pairs) {
    // The changes a single setting can make: a mistake on, the other resolve, another
    // integrator.
    std::vector<Change> single;
    for (int m = 0; m < static_cast<int>(Mistake::Count); ++m)
        if (!reference.has(static_cast<Mistake>(m))) single.push_back({ChangeKind::Mistake, m});
    for (int r = 0; r < static_cast<int>(Resolve::Count); ++r)
        if (r != static_cast<int>(reference.resolve)) single.push_back({ChangeKind::Resolve, r});
    for (int i = 0; i < static_cast<int>(Integrator::Count); ++i)
        if (i != static_cast<int>(reference.integrator))
            single.push_back({ChangeKind::Integrator, i});

    // The reference's method first, then the others in the lecture's order.
    std::vector<int> methods{static_cast<int>(reference.method)};
    for (int m = 0; m < static_cast<int>(Method::Count); ++m)
        if (m != methods.front()) methods.push_back(m);

    std::vector<Variant> out;
    auto add = [&](std::vector<Change> changes) {
        Variant v;
        v.settings = reference;
        for (const Change& c : changes) apply(v.settings, c);
        v.changes = std::move(changes);
        out.push_back(std::move(v));
    };
    for (int method : methods) {
        std::vector<Change> base;
        if (method != methods.front()) base.push_back({ChangeKind::Method, method});
        add(base);
        for (const Change& c : single) {
            std::vector<Change> changes = base;
            changes.push_back(c);
            add(changes);
        }
    }
    if (pairs)
        for (int method : methods)
            for (std::size_t a = 0; a < single.size(); ++a)
                for (std::size_t b = a + 1; b < single.size(); ++b) {
                    if (single[a].kind != ChangeKind::Mistake ||
                        single[b].kind != ChangeKind::Mistake)
                        continue;
                    std::vector<Change> changes;
                    if (method != methods.front()) changes.push_back({ChangeKind::Method, method});
                    changes.push_back(single[a]);
                    changes.push_back(single[b]);
                    add(changes);
                }
    return out;
}
