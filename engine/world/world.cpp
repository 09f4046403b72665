#include "world.h"

#include <cstring>
#include <iterator>

namespace {

// One table of names per setting, read by the name functions and the parsers below.
constexpr const char* kMethodNames[] = {"perfect", "move-and-correct", "turn-based"};
constexpr const char* kResolveNames[] = {"momentum", "reflect"};
constexpr const char* kIntegratorNames[] = {"semi-implicit-euler", "explicit-euler", "exact"};
constexpr const char* kMistakeNames[] = {"discrete", "move-back", "first-found",
                                         "no-approach-test"};
constexpr const char* kMistakeSlides[] = {
    "Discrete can give errors with high velocities: tunneling",
    "BAD: no exact point of impact",
    "BAD: resolving wrong collision",
    "You'll find collisions that are not really collisions (check the relative velocity)",
};
static_assert(std::size(kMethodNames) == static_cast<size_t>(Method::Count));
static_assert(std::size(kResolveNames) == static_cast<size_t>(Resolve::Count));
static_assert(std::size(kIntegratorNames) == static_cast<size_t>(Integrator::Count));
static_assert(std::size(kMistakeNames) == static_cast<size_t>(Mistake::Count));
static_assert(std::size(kMistakeSlides) == static_cast<size_t>(Mistake::Count));

template <typename E, size_t N> const char* nameIn(const char* const (&names)[N], E value) {
    const auto i = static_cast<size_t>(value);
    return i < N ? names[i] : "unknown";
}
template <typename E, size_t N>
bool parseIn(const char* const (&names)[N], const char* name, E& value) {
    for (size_t i = 0; i < N; ++i) {
        if (std::strcmp(name, names[i]) == 0) {
            value = static_cast<E>(i);
            return true;
        }
    }
    return false;
}

} // namespace

const char* methodName(Method method) {
    return nameIn(kMethodNames, method);
}
bool parseMethod(const char* name, Method& method) {
    return parseIn(kMethodNames, name, method);
}
const char* resolveName(Resolve resolve) {
    return nameIn(kResolveNames, resolve);
}
bool parseResolve(const char* name, Resolve& resolve) {
    return parseIn(kResolveNames, name, resolve);
}
const char* integratorName(Integrator integrator) {
    return nameIn(kIntegratorNames, integrator);
}
bool parseIntegrator(const char* name, Integrator& integrator) {
    return parseIn(kIntegratorNames, name, integrator);
}
const char* mistakeName(Mistake mistake) {
    return nameIn(kMistakeNames, mistake);
}
bool parseMistake(const char* name, Mistake& mistake) {
    return parseIn(kMistakeNames, name, mistake);
}
const char* mistakeSlide(Mistake mistake) {
    return nameIn(kMistakeSlides, mistake);
}

WorldSettings defaultWorldSettings() {
    return WorldSettings{};
}

Vec2 totalMomentum(const World& world) {
    Vec2 p;
    for (const Block& b : world.blocks)
        if (b.isDynamic()) p += momentumOf(b);
    return p;
}

double kineticEnergy(const World& world) {
    double e = 0.0;
    for (const Block& b : world.blocks)
        if (b.isDynamic()) e += kineticEnergyOf(b);
    return e;
}

double potentialEnergy(const World& world) {
    double e = 0.0;
    for (const Block& b : world.blocks)
        if (b.isDynamic()) e += potentialEnergyOf(world, b);
    return e;
}

std::uint64_t stateHash(const World& world) {
    std::uint64_t hash = 1469598103934665603ull; // FNV-1a offset basis
    auto mix = [&hash](double value) {
        std::uint64_t bits;
        std::memcpy(&bits, &value, sizeof bits);
        for (int i = 0; i < 8; ++i) {
            hash ^= (bits >> (8 * i)) & 0xffu;
            hash *= 1099511628211ull; // FNV prime
        }
    };
    mix(world.time);
    for (const Block& b : world.blocks) {
        mix(b.position.x), mix(b.position.y), mix(b.velocity.x), mix(b.velocity.y);
    }
    return hash;
}
