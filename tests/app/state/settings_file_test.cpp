// The settings file is input too (issue 28): a corrupt, huge, hostile or unreadable settings file
// never stops the app from starting. Each case gives the defaults (or the good lines' values) and
// a warning naming the file and, for a line, its number; nothing blocks or reads without bound.
#include "app_config.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct ConfigFolder {
    fs::path dir;
    explicit ConfigFolder(const std::string& name) {
        dir = fs::temp_directory_path() /
              ("sandbox_settings_" + name + "_" + std::to_string(::getpid())) / "collision-sandbox";
        fs::remove_all(dir.parent_path());
        fs::create_directories(dir);
    }
    ~ConfigFolder() { fs::remove_all(dir.parent_path()); }
    std::string file() const { return (dir / "settings.txt").string(); }
    void write(const std::string& text) const { std::ofstream(file(), std::ios::binary) << text; }
};

bool anyContains(const std::vector<std::string>& warnings, const std::string& part) {
    for (const std::string& w : warnings)
        if (w.find(part) != std::string::npos) return true;
    return false;
}

std::string joined(const std::vector<std::string>& warnings) {
    std::string all;
    for (const std::string& w : warnings) all += w + "\n";
    return all;
}

bool isDefault(const AppConfig& c) {
    const AppConfig d;
    return c.uiScale == d.uiScale && c.labelScale == d.labelScale && c.volume == d.volume &&
           c.windowWidth == d.windowWidth && c.windowHeight == d.windowHeight &&
           c.lastScene.empty() && c.sound == d.sound && c.lightTheme == d.lightTheme;
}

} // namespace

TEST(SettingsFile, BadValuesKeepTheDefaultWithTheirLine) {
    std::vector<std::string> w;
    const AppConfig c = parseAppConfig(
        "# comment\nui_scale = nan\nlabel_scale = inf\nvolume = banana\nwindow_width = 1e999\n"
        "sound = loud\nlight_theme = maybe\n",
        "settings.txt", &w);
    EXPECT_TRUE(isDefault(c));
    EXPECT_TRUE(anyContains(w, "settings.txt:2: ui_scale: 'nan' is not a number")) << joined(w);
    EXPECT_TRUE(anyContains(w, "settings.txt:3: label_scale: 'inf'")) << joined(w);
    EXPECT_TRUE(anyContains(w, "settings.txt:4: volume: 'banana'")) << joined(w);
    EXPECT_TRUE(anyContains(w, "settings.txt:5: window_width: '1e999'")) << joined(w);
    EXPECT_TRUE(anyContains(w, "settings.txt:6: sound: 'loud'")) << joined(w);
    EXPECT_TRUE(anyContains(w, "settings.txt:7: light_theme: 'maybe'")) << joined(w);
}

TEST(SettingsFile, OutOfRangeIsClampedWithAWarning) {
    std::vector<std::string> w;
    const AppConfig c =
        parseAppConfig("ui_scale = 99\nvolume = -1\nwindow_height = 5\n", "s.txt", &w);
    EXPECT_EQ(c.uiScale, kMaxUiScale);
    EXPECT_EQ(c.volume, 0.0f);
    EXPECT_EQ(c.windowHeight, 240);
    EXPECT_TRUE(anyContains(w, "s.txt:1: ui_scale: '99' is outside")) << joined(w);
    EXPECT_TRUE(anyContains(w, "s.txt:3: window_height: '5' is outside 240 to 16384")) << joined(w);
}

TEST(SettingsFile, JunkLinesAndControlBytesAreEscapedAndCounted) {
    std::string junk = "ui_scale = 1.5\n\x1b]0;owned\x07\n";
    for (int i = 0; i < 1000; ++i) junk += "garbage line\n";
    std::vector<std::string> w;
    const AppConfig c = parseAppConfig(junk, "settings.txt", &w);
    EXPECT_EQ(c.uiScale, 1.5f); // the good line is kept
    EXPECT_TRUE(anyContains(w, "settings.txt:2: not a 'key = value' line: '\\x1b]0;owned\\x07'"))
        << joined(w);
    for (const std::string& line : w) EXPECT_EQ(line.find('\x1b'), std::string::npos);
    EXPECT_EQ(w.size(), kMaxSettingsWarnings + 1); // bounded, the rest counted
    EXPECT_TRUE(anyContains(w, "981 more bad lines")) << w.back();
}

TEST(SettingsFile, TooLargeGivesTheDefaults) {
    ConfigFolder folder("large");
    folder.write("ui_scale = 2\n" + std::string(kMaxSettingsBytes, '#'));
    std::vector<std::string> w;
    EXPECT_TRUE(isDefault(loadAppConfig(folder.dir.string(), &w)));
    EXPECT_TRUE(anyContains(w, folder.file() + ": larger than 1 MiB")) << joined(w);
}

TEST(SettingsFile, FifoDoesNotBlock) {
    ConfigFolder folder("fifo");
    ASSERT_EQ(mkfifo(folder.file().c_str(), 0600), 0);
    std::vector<std::string> w;
    EXPECT_TRUE(isDefault(loadAppConfig(folder.dir.string(), &w))); // returns: no writer needed
    EXPECT_TRUE(anyContains(w, folder.file() + ": not a regular file")) << joined(w);
}

TEST(SettingsFile, DeviceIsNotRead) {
    ConfigFolder folder("device");
    fs::create_symlink("/dev/zero", folder.dir / "settings.txt");
    std::vector<std::string> w;
    EXPECT_TRUE(isDefault(loadAppConfig(folder.dir.string(), &w))); // not a byte of /dev/zero
    EXPECT_TRUE(anyContains(w, ": not a regular file")) << joined(w);
}

TEST(SettingsFile, DirectoryInItsPlace) {
    ConfigFolder folder("dir");
    fs::create_directory(folder.file());
    std::vector<std::string> w;
    EXPECT_TRUE(isDefault(loadAppConfig(folder.dir.string(), &w)));
    EXPECT_FALSE(w.empty());
}

TEST(SettingsFile, LastSceneThatCannotOpenIsDropped) {
    ConfigFolder folder("last");
    const fs::path fifo = folder.dir / "pipe.json";
    ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
    const std::pair<std::string, std::string> cases[] = {
        {"/dev/zero", "is not a regular file"},
        {fifo.string(), "is not a regular file"},
        {folder.dir.string(), "is not a regular file"},
        {(folder.dir / "gone.json").string(), "is gone"},
        {"scenes/relative.json", "is not an absolute path"}};
    for (const auto& [scene, why] : cases) {
        folder.write("ui_scale = 1.25\nlast_scene = " + scene + "\n");
        std::vector<std::string> w;
        const AppConfig c = loadAppConfig(folder.dir.string(), &w);
        EXPECT_EQ(c.lastScene, "") << scene;
        EXPECT_EQ(c.uiScale, 1.25f) << scene;
        EXPECT_TRUE(anyContains(w, folder.file() + ":2: last_scene ")) << joined(w);
        EXPECT_TRUE(anyContains(w, why)) << joined(w);
    }
}

TEST(SettingsFile, RepairedOnTheNextSave) {
    ConfigFolder folder("repair");
    ASSERT_EQ(mkfifo(folder.file().c_str(), 0600), 0);
    AppConfig c;
    c.uiScale = 1.5f;
    ASSERT_TRUE(saveAppConfig(folder.dir.string(), c));
    EXPECT_TRUE(fs::is_regular_file(folder.file()));
    std::vector<std::string> w;
    EXPECT_EQ(loadAppConfig(folder.dir.string(), &w).uiScale, 1.5f);
    EXPECT_TRUE(w.empty()) << joined(w);
}

TEST(SettingsFile, LinkToADeviceIsReplacedNotWrittenThrough) {
    ConfigFolder folder("devlink");
    fs::create_symlink("/dev/null", folder.dir / "settings.txt");
    ASSERT_TRUE(saveAppConfig(folder.dir.string(), AppConfig{}));
    EXPECT_FALSE(fs::is_symlink(folder.dir / "settings.txt"));
    EXPECT_TRUE(fs::is_regular_file(folder.file()));
    struct stat st {};
    ASSERT_EQ(stat("/dev/null", &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
}

// Issue 28's outside suite: a settings.txt linked to a file in another folder was written
// through on exit. It is replaced: nothing is written outside the settings folder. A link to a
// file of the folder itself is still followed.
TEST(SettingsFile, LinkToAFileElsewhereIsReplacedNotWrittenThrough) {
    ConfigFolder folder("outlink");
    const fs::path outside = folder.dir.parent_path() / "outside.txt";
    std::ofstream(outside) << "ui_scale = 2\n";
    fs::create_symlink(outside, folder.dir / "settings.txt");
    ASSERT_TRUE(saveAppConfig(folder.dir.string(), AppConfig{}));
    EXPECT_FALSE(fs::is_symlink(folder.dir / "settings.txt"));
    EXPECT_TRUE(fs::is_regular_file(folder.file()));
    std::ifstream in(outside);
    const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(kept, "ui_scale = 2\n");

    std::ofstream(folder.dir / "mine.txt") << "ui_scale = 2\n";
    fs::remove(folder.dir / "settings.txt");
    fs::create_symlink("mine.txt", folder.dir / "settings.txt");
    ASSERT_TRUE(saveAppConfig(folder.dir.string(), AppConfig{}));
    EXPECT_TRUE(fs::is_symlink(folder.dir / "settings.txt"));
    EXPECT_EQ(loadAppConfig(folder.dir.string()).uiScale, AppConfig{}.uiScale);
}
