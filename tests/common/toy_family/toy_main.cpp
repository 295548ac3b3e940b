// gridcull-toy: the gridcull executable with the test-only toy family
// registered (toy_family.h), so the screenshot tests can draw its panel and
// overlay exactly as the window does.
#include <cstdio>
#include <string>

#include "app/cli.h"
#include "tests/common/toy_family/toy_family.h"

int main(int argc, char** argv) {
    std::string error;
    if (!gridcull::test::registerToyFamily(error)) {
        std::fprintf(stderr, "gridcull-toy: %s\n", error.c_str());
        return 1;
    }
    return gridcull::runCli(argc, argv);
}
