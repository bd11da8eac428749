#include "src/check/quality_histogram.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "src/check/validity.hpp"

namespace loom {

std::size_t QualityHistogram::total() const { return std::accumulate(counts.begin(), counts.end(), std::size_t{0}); }

void QualityHistogram::add(double sj) {
  const auto last = static_cast<long>(counts.size()) - 1;
  const long bin = std::isnan(sj) ? 0 : static_cast<long>(std::floor((sj - kFrom) / kWidth));
  ++counts[static_cast<std::size_t>(std::clamp(bin, 0L, last))];
}

QualityHistogram quality_histogram(const HexMesh& mesh) {
  QualityHistogram h;
  for (std::size_t hex = 0; hex < mesh.hexes.size(); ++hex) h.add(scaled_jacobian(mesh, hex));
  return h;
}

nlohmann::json histogram_json(const QualityHistogram& h) {
  return {{"from", QualityHistogram::kFrom}, {"width", QualityHistogram::kWidth}, {"counts", h.counts}};
}

namespace {

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

}  // namespace

std::string histogram_svg(const QualityHistogram& h, const std::string& title) {
  constexpr double left = 60, top = 40, width = 600, height = 300, bar = width / 20;
  const std::size_t most = std::max<std::size_t>(1, *std::max_element(h.counts.begin(), h.counts.end()));
  std::string out = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" font-family=\"sans-serif\" "
      "font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      "<text x=\"{}\" y=\"20\" font-size=\"14\">{}</text>\n",
      left + width + 20, top + height + 50, left, xml_escaped(title));
  for (std::size_t i = 0; i < h.counts.size(); ++i) {
    const double low = QualityHistogram::kFrom + static_cast<double>(i) * QualityHistogram::kWidth;
    const char* colour = low < 0 ? "#c03030" : low < 0.2 ? "#e09020" : "#40a040";
    const double tall = height * static_cast<double>(h.counts[i]) / static_cast<double>(most);
    out += fmt::format("<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"{}\"><title>[{:.1f}, "
                       "{:.1f}): {}</title></rect>\n",
                       left + static_cast<double>(i) * bar + 1, top + height - tall, bar - 2, tall, colour, low,
                       low + QualityHistogram::kWidth, h.counts[i]);
  }
  out += fmt::format("<line x1=\"{0}\" y1=\"{1}\" x2=\"{2}\" y2=\"{1}\" stroke=\"black\"/>\n", left, top + height,
                     left + width);
  for (int tick = -10; tick <= 10; tick += 5)
    out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">{:.1f}</text>\n",
                       left + (tick + 10) * bar, top + height + 18, tick / 10.0);
  out += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">scaled Jacobian ({} hexes)</text>\n",
                     left + width / 2, top + height + 40, h.total());
  out += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">{}</text>\n", left - 6, top + 4, most);
  out += fmt::format("<text x=\"{}\" y=\"{:.1f}\" text-anchor=\"end\">0</text>\n</svg>\n", left - 6, top + height);
  return out;
}

}  // namespace loom
