// A check the tests share: a text (an error, a log) says a part somewhere in it; the failure shows
// the whole text.
#pragma once

#include <gtest/gtest.h>

#include <string>

inline ::testing::AssertionResult says(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "\"" << text << "\" does not say \"" << part << "\"";
}
