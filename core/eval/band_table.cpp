#include "core/eval/detail/band_table.hpp"

#include <cmath>
#include <sstream>

#include "core/common/number_text.hpp"
#include "core/eval/eval_report.hpp"
#include "core/eval/yaw_bands.hpp"

namespace clm3d {
namespace {

// "97.0%", or "n/a" for no faces.
std::string bandPercent(int part, int whole) {
  return whole > 0 ? fixedText(100.0 * part / whole, 1, "") + "%" : std::string("n/a");
}

std::string bandRange(const BandTable& table, std::size_t k) {
  return yawBandLabels(table.edges).at(k);
}

}  // namespace

std::string formatBandLines(const BandTable& table) {
  std::ostringstream out;
  out << "yaw bands (" << table.source << "; " << table.unbanded << ' ' << table.faceWord
      << " in no band)\n";
  for (std::size_t k = 0; k + 1 < table.edges.size(); ++k) {
    for (std::size_t m = 0; m < table.rows.size(); ++m) {
      const BandFigures& band = table.rows[m][k];
      out << "|yaw| " << bandRange(table, k) << "  " << table.labels[m] << "  " << table.faceWord
          << ' ' << band.faces << "  fitted " << band.fitted << " ("
          << bandPercent(band.fitted, band.faces) << ")  error/box "
          << formatErrorValue(band.boxError) << "  median " << formatErrorValue(band.medianBoxError)
          << "  error/eye " << formatErrorValue(band.eyeError) << "  within "
          << fixedText(table.threshold, 2, "") << ": "
          << (std::isfinite(band.foundShare) ? fixedText(100.0 * band.foundShare, 1, "") + "%"
                                             : std::string("n/a"));
      if (band.offFace >= 0) {
        out << "  off the face (error/box > " << fixedText(table.offFaceAbove, 2, "")
            << "): " << band.offFace;
      }
      out << '\n';
    }
  }
  return out.str();
}

std::string formatBandMarkdown(const BandTable& table, const std::string& facesTitle) {
  std::ostringstream out;
  out << "| \\|yaw\\| | " << facesTitle << " |";
  for (const std::string& label : table.labels) {
    out << ' ' << label << " fitted | " << label << " error / box |";
  }
  out << "\n|---|---|";
  for (std::size_t m = 0; m < table.labels.size(); ++m) out << "---|---|";
  out << '\n';
  for (std::size_t k = 0; k + 1 < table.edges.size(); ++k) {
    out << "| " << bandRange(table, k) << " | " << (table.rows.empty() ? 0 : table.rows[0][k].faces)
        << " |";
    for (const auto& row : table.rows) {
      out << ' ' << row[k].fitted << " (" << bandPercent(row[k].fitted, row[k].faces) << ") | "
          << formatErrorValue(row[k].boxError) << " |";
    }
    out << '\n';
  }
  return out.str();
}

}  // namespace clm3d
