// JsonValue (app/edit/edit.h): an edit's value held through a pointer so that edit.h needs only
// json_fwd.hpp. It must behave as the json it holds: empty reads as null, a copy is independent,
// a move leaves the source null (never a dangling pointer), self-assignment keeps the value.
#include "edit.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <utility>

namespace {

using json = nlohmann::json;

TEST(JsonValue, emptyReadsAsNull) {
    const JsonValue empty;
    EXPECT_TRUE((*empty).is_null());
    EXPECT_TRUE(empty->is_null());
    const Edit edit; // an Edit's value starts empty
    EXPECT_TRUE(edit.value->is_null());
}

TEST(JsonValue, holdsItsValue) {
    const JsonValue v(json{{"mass", 2.5}});
    EXPECT_EQ(*v, (json{{"mass", 2.5}}));
    const JsonValue s = json("static");
    EXPECT_EQ(*s, json("static"));
}

TEST(JsonValue, writingThroughAnEmptyValueCreatesIt) {
    JsonValue v;
    *v = 3;
    EXPECT_EQ(*v, json(3));
}

TEST(JsonValue, aCopyIsIndependent) {
    JsonValue a(json::array({1, 2}));
    JsonValue b(a);
    (*b).push_back(3);
    EXPECT_EQ(*a, json::array({1, 2}));
    EXPECT_EQ(*b, json::array({1, 2, 3}));
    JsonValue c;
    c = a;
    *a = "changed";
    EXPECT_EQ(*c, json::array({1, 2}));
    JsonValue empty;
    c = empty; // copying an empty value empties the target
    EXPECT_TRUE(c->is_null());
}

TEST(JsonValue, aMoveLeavesTheSourceNull) {
    JsonValue a(json(7));
    JsonValue b(std::move(a));
    EXPECT_EQ(*b, json(7));
    EXPECT_TRUE(std::as_const(a)->is_null()); // NOLINT(bugprone-use-after-move): defined state
    JsonValue c(json(1));
    c = std::move(b);
    EXPECT_EQ(*c, json(7));
    EXPECT_TRUE(std::as_const(b)->is_null()); // NOLINT(bugprone-use-after-move)
}

TEST(JsonValue, selfAssignmentKeepsTheValue) {
    JsonValue a(json{{"x", 1}});
    JsonValue& alias = a;
    a = alias;
    EXPECT_EQ(*a, (json{{"x", 1}}));
    a = std::move(alias);
    EXPECT_EQ(*a, (json{{"x", 1}}));
}

} // namespace
