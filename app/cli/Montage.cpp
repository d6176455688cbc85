// The compare montage (Montage.h): ui/FigureKit.h on Qt's offscreen platform.
#include "Montage.h"

#include "Chart.h"

#if SHADOWLAB_CLI_CHARTS
#include "FigureKit.h"
#endif

namespace sl::cli {

std::optional<std::string> writeMontage(const std::vector<sl::ui::FigureCell>& cells,
                                        const std::string& title, int columns,
                                        const std::optional<sl::ui::FigureInset>& inset,
                                        const std::string& pngPath) {
#if SHADOWLAB_CLI_CHARTS
  if (cells.empty()) return "--montage: no configurations to show";
  ensureOffscreenApplication();
  if (!sl::ui::drawFigure(cells, title, columns, inset)
           .save(QString::fromStdString(pngPath), "PNG"))
    return "--montage: cannot write '" + pngPath + "'";
  return std::nullopt;
#else
  (void)cells, (void)title, (void)columns, (void)inset, (void)pngPath;
  return "--montage: this shadowlab-cli was built without Qt (the montage draws its labels "
         "with Qt); install Qt 6 and rebuild";
#endif
}

}  // namespace sl::cli
