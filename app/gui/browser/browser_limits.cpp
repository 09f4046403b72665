#include "browser_limits.h"

#include "printable.h"
#include "student_trace.h"

#include <cstdio>
#include <filesystem>

namespace {

std::string fileName(const std::string& path) {
    return printable(std::filesystem::path(path).filename().string());
}

} // namespace

std::string byteSize(std::uintmax_t bytes) {
    char text[48];
    if (bytes < 1000)
        std::snprintf(text, sizeof text, "%ju bytes", bytes);
    else if (bytes < 1000u * 1024u)
        std::snprintf(text, sizeof text, "%.0f KB", static_cast<double>(bytes) / 1024.0);
    else
        std::snprintf(text, sizeof text, "%.1f MB", static_cast<double>(bytes) / (1024.0 * 1024.0));
    return text;
}

std::string browserOpenRefusal(const std::string& path, std::uintmax_t bytes) {
    const bool trace = isTraceFile(path);
    const std::uintmax_t limit = trace ? kMaxBrowserTraceBytes : kMaxBrowserSceneBytes;
    if (bytes <= limit) return "";
    return fileName(path) + " is " + byteSize(bytes) + ": the browser opens " +
           (trace ? "traces" : "scene files") + " of up to " + byteSize(limit) +
           " (it has one thread, which the page's keys would wait for). Open it in the sandbox's "
           "window or with sandbox-cli " +
           (trace ? "compare" : "run") + ", which take larger files.";
}

std::string openingMessage(const std::string& path, std::uintmax_t bytes) {
    return "Opening " + fileName(path) + " (" + byteSize(bytes) + ")...";
}
