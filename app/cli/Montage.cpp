// The compare montage (Montage.h): renderer/figures/FigureKit.h on Qt's offscreen platform.
#include "Montage.h"

#include <stdexcept>

#include "Chart.h"
#include "CliCommon.h"

#if SHADOWLAB_CLI_CHARTS
#include "figures/FigureKit.h"
#endif

namespace sl::cli {

std::optional<std::string> montageUnavailable() {
#if SHADOWLAB_CLI_CHARTS
  return std::nullopt;
#else
  return "--montage: this shadowlab-cli was built without Qt (the montage draws its labels "
         "with Qt); install Qt 6 and rebuild";
#endif
}

void writeMontage(const std::vector<sl::ui::FigureCell>& cells, const std::string& title,
                  int columns, const std::optional<sl::ui::FigureInset>& inset,
                  const std::string& pngPath) {
#if SHADOWLAB_CLI_CHARTS
  ensureOffscreenApplication();
  const QImage figure = sl::ui::drawFigure(cells, title, columns, inset);
  writeAtomically(pngPath, [&](const std::string& path) { return savePng(figure, path); });
#else
  (void)cells, (void)title, (void)columns, (void)inset;
  throw std::runtime_error(pngPath + ": " + montageUnavailable().value_or(""));
#endif
}

}  // namespace sl::cli
