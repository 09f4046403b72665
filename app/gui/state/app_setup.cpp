#include "app_setup.h"

#ifndef SANDBOX_SCENES_DIR
#define SANDBOX_SCENES_DIR ""
#endif

std::string builtInScenesDirectory() {
    return SANDBOX_SCENES_DIR;
}

bool setupApp(App& app, const Options& options, const std::string& lastScene, std::string* error) {
    app.scenesDir = findScenesDirectory(executableDirectory(), builtInScenesDirectory());
    app.sceneFiles = listScenes(app.scenesDir);
    app.verbose = options.verbose;
    if (options.showGiven) applyShowSet(app, options.show);

    if (!options.scene.empty()) {
        const std::string path = resolveScenePath(options.scene, app.scenesDir);
        if (!loadScene(app, path)) {
            if (error) *error = app.error;
            return false;
        }
        return true;
    }
    if (!lastScene.empty() && loadScene(app, lastScene)) return true;
    const std::string fallback = resolveScenePath(kDefaultSceneFile, app.scenesDir);
    if (loadScene(app, fallback)) return true;
    // Nothing loads: an empty world, with the reason on screen.
    Scene empty;
    empty.name = "(no scene)";
    const std::string why = app.error;
    setScene(app, empty, "");
    app.error = why.empty() ? "No scene found" : why;
    return true;
}
