// A load error of a scene file or a file format built on it (lessons), below both scene.h and
// scene_json.h so that neither includes the other for it.
#pragma once

#include "printable.h"

#include <string>

// A load error: `where` names the place ("scene.json:3:14" for syntax, "scene.json: blocks[3].mass"
// for a bad value) and `message` says what is wrong.
struct SceneError {
    std::string where;
    std::string message;
    std::string text() const { return where + ": " + message; }
};

// Every load error leaves through here: its place (with the file's name) and message printable and
// bounded, whatever the file's name and contents (a key, a name or a number can be megabytes).
inline SceneError sceneError(const std::string& where, const std::string& message) {
    return {printable(where, kPrintablePath), printable(message, 4 * kPrintableDefault)};
}
