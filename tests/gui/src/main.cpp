// shadowlab-gui-tests: the GUI tests' program (not installed). `shadowlab-gui-tests --test
// NAME[=ARG] [shadowlab's options]` opens the window as `shadowlab` does with the same options
// (ui/launch/Launch.h), then runs GUI test NAME on it (GuiTests.h). Exit codes: 0 pass, 1 fail (or
// a runtime failure), 2 bad command line: no --test, an unknown test name, or shadowlab's.
#include <cstdio>
#include <cstring>
#include <vector>

#include <QString>

#include "GuiTests.h"
#include "launch/Launch.h"
#include "window/MainWindow.h"

int main(int argc, char** argv) {
  // --test NAME[=ARG] (or --test=NAME[=ARG]) is ours; every other argument is shadowlab's.
  std::vector<char*> rest;
  QString spec;
  bool given = false;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--test") == 0 && i + 1 < argc) {
      spec = QString::fromLocal8Bit(argv[++i]);
      given = true;
    } else if (std::strncmp(argv[i], "--test=", 7) == 0) {
      spec = QString::fromLocal8Bit(argv[i] + 7);
      given = true;
    } else {
      rest.push_back(argv[i]);
    }
  }
  const QString name = spec.section(QLatin1Char('='), 0, 0);
  const QString argument = spec.section(QLatin1Char('='), 1);
  const sl::ui::GuiTests::Test* test = sl::ui::GuiTests::find(name);
  if (!given || !test) {
    std::fprintf(stderr, "shadowlab-gui-tests: %s (known: %s)\n",
                 given ? qPrintable(QStringLiteral("unknown test '%1'").arg(name))
                       : "usage: shadowlab-gui-tests --test NAME[=ARG] [shadowlab options]",
                 qPrintable(sl::ui::GuiTests::usage()));
    return 2;
  }
  int restCount = static_cast<int>(rest.size());
  rest.push_back(nullptr);
  return sl::ui::runGui(restCount, rest.data(), [test, argument](sl::ui::MainWindow& window) {
    (new sl::ui::GuiTests(window))->start(*test, argument);
  });
}
