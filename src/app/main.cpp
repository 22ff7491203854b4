// The stackbook program (chapter 10). Everything is in runCli (cli.cpp).
#include "cli.hpp"

int main(int argc, char** argv) { return stackbook::app::runCli(argc, argv); }
