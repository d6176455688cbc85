// shadowlab: the interactive GUI. `shadowlab [--scene NAME|FILE] [--technique ID]
// [--set KEY=VALUE]... [--lesson N|NAME|FILE] [--course NAME] [--grab DIR --grab-after N]`; see
// ui/launch/Launch.h, ui/window/MainWindow.h and ui/launch/LaunchOptions.h.
// Exit codes: 0 ok, 1 runtime failure (no GL 4.5, scene not loadable, grab failed),
// 2 bad command line (unknown option, technique or parameter, value out of range).
#include "launch/Launch.h"

int main(int argc, char** argv) {
  return sl::ui::runGui(argc, argv);
}
