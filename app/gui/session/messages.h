// What the app tells the user in the controls panel: the last error (a file that did not load or
// save, a bad step number, a bad URL parameter) and the last note (what an action did). Set by
// the app and the lesson session, shown until replaced or cleared.
#pragma once

#include <string>

struct Messages {
    std::string error;
    std::string note;
    void clear() { error.clear(), note.clear(); }
};
