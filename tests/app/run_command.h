// Runs the real gridcull executable in a shell and captures what it prints.
#pragma once
#include <sys/wait.h>
#include <unistd.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace gridcull::test {

struct CommandResult {
    int status = -1;  // exit status, or -1 when it did not exit normally (a crash)
    std::string out;
    std::string err;
};

inline std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline std::string scratchDir() {
    const char* tmp = std::getenv("TMPDIR");
    std::string dir =
        std::string(tmp ? tmp : "/tmp") + "/gridcull-test-" + std::to_string(::getpid());
    std::system(("mkdir -p '" + dir + "'").c_str());
    return dir;
}

// Runs `command` (shell text) with no input.
inline CommandResult runCommand(const std::string& command) {
    static int counter = 0;
    const std::string base = scratchDir() + "/cmd" + std::to_string(counter++);
    const std::string cmd = command + " >'" + base + ".out' 2>'" + base + ".err' </dev/null";
    const int raw = std::system(cmd.c_str());
    CommandResult r;
    r.status = (raw != -1 && WIFEXITED(raw)) ? WEXITSTATUS(raw) : -1;
    // The shell reports a signal-killed child as 128 + signal.
    if (r.status > 128) r.status = -1;
    r.out = readWholeFile(base + ".out");
    r.err = readWholeFile(base + ".err");
    std::remove((base + ".out").c_str());
    std::remove((base + ".err").c_str());
    return r;
}

// `args` is appended to the executable's path as shell text.
inline CommandResult runGridcull(const std::string& args) {
    return runCommand(std::string("'") + GRIDCULL_EXE + "' " + args);
}

inline std::string sourcePath(const std::string& relative) {
    return std::string(GRIDCULL_SOURCE_DIR) + "/" + relative;
}

}  // namespace gridcull::test
