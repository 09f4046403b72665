// What the lesson tests load lessons with: the shipped scenes and the overlay table's names, as
// sandbox-cli does.
#pragma once

#include "lesson.h"
#include "vocabulary.h"

inline LessonContext shippedLessonContext() {
    LessonContext c;
    c.scenesDir = SANDBOX_SCENES_DIR;
    c.overlayNames = overlayNames();
    return c;
}
