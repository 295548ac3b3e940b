// gridcull: the desktop debugger and the headless command line in one executable.
#include "app/cli.h"

int main(int argc, char** argv) { return gridcull::runCli(argc, argv); }
