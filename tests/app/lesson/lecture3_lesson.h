// lessons/lecture3.json as the lesson library reads it, loaded once: the lesson sweeps' own
// account of the steps (lesson_sweep_test.cpp, lesson_screens_test.cpp).
#pragma once

#include "lesson.h"

#include <gtest/gtest.h>

#include <string>

inline const Lesson& lecture3() {
    static const Lesson lesson = [] {
        LessonContext context;
        context.scenesDir = SANDBOX_SCENES_DIR;
        LessonResult loaded =
            loadLessonFile(std::string(SANDBOX_LESSONS_DIR) + "/lecture3.json", context);
        EXPECT_TRUE(loaded.lesson.has_value()) << loaded.error.message;
        return loaded.lesson.value_or(Lesson{});
    }();
    return lesson;
}
