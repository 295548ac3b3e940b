// tests/scenes/bad/expected.tsv: one malformed scene file per line and the text
// its rejection message must contain (the JSON path, or line:column for syntax).
// Read by the loader's tests and by the command line's tests alike.
#pragma once
#include <fstream>
#include <string>
#include <vector>

namespace gridcull::test {

struct BadScene {
    std::string file;      // name inside tests/scenes/bad/
    std::string expected;  // text the message must contain
};

inline std::vector<BadScene> readBadSceneManifest(const std::string& source_dir) {
    std::vector<BadScene> cases;
    std::ifstream in(source_dir + "/tests/scenes/bad/expected.tsv");
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        const size_t tab = line.find('\t');
        if (tab == std::string::npos) continue;
        cases.push_back({line.substr(0, tab), line.substr(tab + 1)});
    }
    return cases;
}

}  // namespace gridcull::test
