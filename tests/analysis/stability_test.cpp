// The stability matrix's known outcomes: a change of behaviour either way (a method that stops
// failing, or starts) makes one of these fail, and the README's matrix must then be updated.
#include "stability.h"

#include <gtest/gtest.h>

#include <map>

namespace {

const std::map<std::pair<std::string, std::string>, StabilityResult>& matrix() {
    static const auto results = [] {
        std::map<std::pair<std::string, std::string>, StabilityResult> m;
        for (const StabilityResult& r : runStability(SANDBOX_SCENES_DIR))
            m[{r.scene, r.method}] = r;
        return m;
    }();
    return results;
}

const StabilityResult& outcome(const std::string& scene, const std::string& method) {
    return matrix().at({scene, method});
}

} // namespace

TEST(Stability, BulletTunnelsOnlyUnderMoveAndCorrect) {
    EXPECT_EQ(outcome("bullet_wall", "move-and-correct").verdict, "tunnels");
    EXPECT_EQ(outcome("bullet_wall", "perfect").verdict, "stopped");
    EXPECT_EQ(outcome("bullet_wall", "turn-based").verdict, "stopped");
}

TEST(Stability, RestingStackHoldsExceptUnderMoveAndCorrect) {
    EXPECT_EQ(outcome("resting_stack", "perfect").verdict, "stable");
    EXPECT_EQ(outcome("resting_stack", "turn-based").verdict, "stable");
    EXPECT_TRUE(outcome("resting_stack", "move-and-correct").fails);
    EXPECT_GT(outcome("resting_stack", "move-and-correct").value, 0.01); // m: it visibly moves
}

TEST(Stability, InelasticCollapseSettlesWithoutOverlapUnderExactMethods) {
    EXPECT_EQ(outcome("inelastic_collapse", "perfect").verdict, "settles");
    EXPECT_EQ(outcome("inelastic_collapse", "turn-based").verdict, "settles");
    EXPECT_TRUE(outcome("inelastic_collapse", "move-and-correct").fails);
}

TEST(Stability, NewtonsCradleEndsWithOnlyTheLastBlockMoving) {
    for (const char* method : {"perfect", "move-and-correct", "turn-based"})
        EXPECT_EQ(outcome("newtons_cradle", method).verdict, "exact") << method;
}

TEST(Stability, CornerHitReversesBothAxesExceptUnderMoveAndCorrect) {
    EXPECT_EQ(outcome("corner_hit", "perfect").verdict, "both axes");
    EXPECT_EQ(outcome("corner_hit", "turn-based").verdict, "both axes");
    EXPECT_EQ(outcome("corner_hit", "move-and-correct").verdict, "y only");
}

TEST(Stability, HighMassRatioCountsPiUnderTheExactMethods) {
    // Galperin: masses 1 and 100^3 collide floor(pi * 1000) = 3141 times, walls included.
    // Turn-based counts them too since it resolves a contact that a bounce closes at once.
    EXPECT_EQ(outcome("high_mass_ratio", "perfect").value, 3141.0);
    EXPECT_FALSE(outcome("high_mass_ratio", "perfect").fails);
    EXPECT_EQ(outcome("high_mass_ratio", "turn-based").value, 3141.0);
    EXPECT_FALSE(outcome("high_mass_ratio", "turn-based").fails);
    EXPECT_TRUE(outcome("high_mass_ratio", "move-and-correct").fails);
}

TEST(Stability, JammedBoxFreezesExactMethodsWithoutOverlap) {
    // Packed edge to edge, nothing can move. The perfect method's collisions repeat at one instant
    // and become perfectly inelastic (no event storm, no cap); turn-based never gets a turn.
    const StabilityResult& perfect = outcome("jammed_box", "perfect");
    EXPECT_EQ(perfect.verdict, "frozen");
    EXPECT_EQ(perfect.value, 0.0); // event-cap hits
    EXPECT_EQ(outcome("jammed_box", "turn-based").verdict, "frozen");
    EXPECT_NE(outcome("jammed_box", "move-and-correct").verdict.find("overlap"), std::string::npos);
}

TEST(Stability, NothingRunsAwayUnderTheExactMethods) {
    // A heavy block dropped on a light one, a pile at C = 0, a block crushed by a platform:
    // turn-based once ended these at 91, 91 and 2,340 m/s with 36x and 3x the energy. Now no
    // block passes 30 m/s and the energy never rises (the platform's scene aside); the blocks
    // fall at most 12 m, so the fastest is the pile's at about 13 m/s.
    for (const char* scene : {"heavy_on_light", "pile", "crushed_block"}) {
        for (const char* method : {"perfect", "turn-based"}) {
            EXPECT_EQ(outcome(scene, method).verdict, "bounded") << scene << ", " << method;
            EXPECT_LT(outcome(scene, method).value, 15.0) << scene << ", " << method; // m/s
        }
        EXPECT_TRUE(outcome(scene, "move-and-correct").fails) << scene; // overlaps
    }
}

TEST(Stability, EachMistakeShowsWhereItsSlideSaysAndNowhereElse) {
    // With the mistake on against off (the shipped scenes have it on).
    EXPECT_EQ(outcome("mistake_discrete", "perfect").verdict, "tunnels");
    EXPECT_EQ(outcome("mistake_discrete", "turn-based").verdict, "tunnels");
    EXPECT_EQ(outcome("mistake_discrete", "move-and-correct").verdict, "unaffected");
    EXPECT_EQ(outcome("mistake_move_back", "turn-based").verdict, "crooked: 1.25 m off");
    EXPECT_EQ(outcome("mistake_move_back", "perfect").verdict, "unaffected");
    EXPECT_EQ(outcome("mistake_first_found", "turn-based").verdict, "overlap 0.5 m");
    EXPECT_EQ(outcome("mistake_first_found", "perfect").verdict, "unaffected");
    EXPECT_EQ(outcome("mistake_no_approach_test", "turn-based").verdict, "2 extra collisions");
    EXPECT_EQ(outcome("mistake_no_approach_test", "perfect").verdict, "unaffected");
    EXPECT_EQ(outcome("mistake_no_approach_test", "move-and-correct").verdict, "unaffected");
}
