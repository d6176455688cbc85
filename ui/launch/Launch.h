// The GUI's start, shared by `shadowlab` and the GUI tests' program (see Launch.cpp).
#pragma once

#include <functional>

namespace sl::ui {

class MainWindow;

/// Drives a window instead of the user: called once the window is shown (the window is then
/// not interactive: no QSettings, problems on stderr); it ends the run with
/// QCoreApplication::exit(code).
using WindowScript = std::function<void(MainWindow&)>;

/// Parses the command line (`shadowlab --help`), opens the window and runs the event loop;
/// returns the exit code (0 ok, 1 runtime failure, 2 bad command line). With `script` the
/// window is driven by it (no --grab needed).
int runGui(int& argc, char** argv, const WindowScript& script = {});

}  // namespace sl::ui
