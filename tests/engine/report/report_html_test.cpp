// report.html (report/report_html.cpp): what it shows comes from report.json's content.
#include "report/report_html.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>

namespace paver {
namespace {

bool has(const std::string& html, const std::string& part) { return html.find(part) != std::string::npos; }

nlohmann::json sample_report() {
  return nlohmann::json::parse(R"json({
    "design": {"units": "mm", "source": "<pendant & co>", "tessellation": "tri", "spacing": 1.6, "gap": 0.1, "margin": 0.3},
    "surface": {"path": "pendant.obj", "faces": 1963, "area": 908.76},
    "verdict": {"ok": false, "problems": ["2 pairs are closer than their radii plus the gap"]},
    "stones": {"count": 367, "carat_total": 4.9545, "carat_rule": "sieve chart",
               "rows": [{"shape": "gem", "diameter_mm": 1.5, "count": 367, "carat_each": 0.0135, "carat_total": 4.9545}]},
    "beads": {"enabled": true, "count": 614, "diameter_mm_min": 0.256, "diameter_mm_max": 0.362},
    "cut": {"cutter": "seat", "thickness": 1, "volume_mm3": 649.8, "shell_volume_mm3": 857.6, "files": ["cut.stl", "cut.3mf"],
            "metal": [{"alloy": "18k yellow gold (750)", "density_g_cm3": 15.5, "grams": 10.07}]},
    "quality_after": {"elements": 367, "contact_violations": 2, "min_clearance": -0.001, "boundary_crossings": 0,
                      "fill": 0.98, "neighbor_ratio": {"p95": 1.07}, "regular_valence_share": 1.0}
  })json");
}

TEST(ReportHtml, ShowsTheVerdictTheStonesTheBeadsAndTheMetalFromTheReport) {
  const std::string html = report_html(sample_report(), "");
  EXPECT_TRUE(has(html, "NOT OK")) << html;
  EXPECT_TRUE(has(html, "<li>2 pairs are closer than their radii plus the gap</li>"));
  // Carats with stones.csv's digits: 4 significant each, 4 decimals in all.
  EXPECT_TRUE(has(html, "<td>gem</td><td>1.50</td><td>367</td><td>0.0135</td><td>4.9545</td>")) << html;
  EXPECT_TRUE(has(html, "<b>4.9545</b>"));
  EXPECT_TRUE(has(html, "<b>614</b>, 0.26 to 0.36 mm"));
  EXPECT_TRUE(has(html, "<h2>Metal with seats (cut.stl, cut.3mf)</h2>")) << "it read (&ndash;)";
  EXPECT_TRUE(has(html, "<td>18k yellow gold (750)</td><td>15.50</td><td>10.07</td>"));
  EXPECT_TRUE(has(html, "&lt;pendant &amp; co&gt;")) << "text from files is escaped";
  EXPECT_FALSE(has(html, "<pendant"));
  EXPECT_TRUE(has(html, "No picture: run with --png"));
}

TEST(ReportHtml, SaysHowABandWasClosed) {
  nlohmann::json report = sample_report();
  EXPECT_FALSE(has(report_html(report, ""), "Band"));
  report["pattern"]["band"] = {{"seamless", true},
                               {"closure", {{"text", "D 1.5 -> 1.52: 40 lattice steps close the band; the stones keep their size, the gap takes the change"}}}};
  EXPECT_TRUE(has(report_html(report, ""), "<p>Band: D 1.5 -&gt; 1.52: 40 lattice steps close the band; the stones keep their size"));
  report["pattern"]["band"] = {{"seamless", false}, {"annulus_because", "the design has edge operators"}};
  EXPECT_TRUE(has(report_html(report, ""), "<p>Band paved as an annulus: the design has edge operators.</p>"));
}

TEST(ReportHtml, SaysHowTheRowsWereTurnedAndWhereTheOffsetWasFitted) {
  nlohmann::json report = sample_report();
  EXPECT_FALSE(has(report_html(report, ""), "Rows along"));
  EXPECT_FALSE(has(report_html(report, ""), "Offset fitted"));
  report["pattern"]["row_alignment"] = {{"axis", "x"}, {"rotation_deg", 26.42}, {"axis_to_surface_deg", 7.2}};
  report["pattern"]["offset_fit"] = {
      {"chosen", {{"shift_in_cells", {0, 0.5}}, {"laid_out", 820}, {"kept", 808}}},
      {"at_design_offset", {{"shift_in_cells", {0, 0}}, {"laid_out", 782}, {"kept", 762}}}};
  const std::string html = report_html(report, "");
  EXPECT_TRUE(has(html, "<p>Rows along x: the pattern turned 26.4 degrees; the axis meets the surface at 7 degrees")) << html;
  EXPECT_TRUE(has(html, "<p>Offset fitted: the lattice shifted (0, 0.5) of a cell, 808 elements kept against 762 at the "
                        "design's offset.</p>")) << html;
  // A pattern too large to pave the finalists: the laid-out counts.
  report["pattern"]["offset_fit"]["chosen"]["kept"] = nullptr;
  EXPECT_TRUE(has(report_html(report, ""), "820 laid out against 782"));
}

TEST(ReportHtml, EmbedsThePreviewSoTheFileStandsAlone) {
  const std::string html = report_html(sample_report(), std::string("\x89PNG\r\n", 6));
  EXPECT_TRUE(has(html, "src=\"data:image/png;base64,iVBORw0K\"")) << html.substr(0, 2000);
  EXPECT_FALSE(has(html, "No picture"));
}

TEST(ReportHtml, Base64IsRfc4648) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
  EXPECT_EQ(base64(std::string("\xff\x00\x80", 3)), "/wCA");
}

}  // namespace
}  // namespace paver
