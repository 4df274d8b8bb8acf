#include "report/report_html.h"

#include "report/bill_of_stones.h"

#include "io/atomic_file.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

namespace paver {
namespace {

using nlohmann::json;

std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string text_of(const json& value) {
  if (value.is_string()) return escaped(value.get<std::string>());
  if (value.is_number_integer() || value.is_number_unsigned()) return std::to_string(value.get<long long>());
  if (value.is_number()) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", value.get<double>());
    return buffer;
  }
  if (value.is_boolean()) return value.get<bool>() ? "yes" : "no";
  return "&ndash;";
}

std::string fixed(const json& value, int decimals) {
  if (!value.is_number()) return "&ndash;";
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value.get<double>());
  return buffer;
}

// As stones.csv writes them (bill_of_stones.h); a dash where a stone is not weighed.
std::string carats(const json& value, std::string (*text)(double)) {
  return value.is_number() ? text(value.get<double>()) : "&ndash;";
}

const json& at(const json& object, const char* key) {
  static const json missing;
  return object.is_object() && object.contains(key) ? object.at(key) : missing;
}

void row(std::string& html, std::initializer_list<std::string> cells, bool header = false) {
  html += "<tr>";
  for (const std::string& cell : cells) html += (header ? "<th>" : "<td>") + cell + (header ? "</th>" : "</td>");
  html += "</tr>\n";
}

}  // namespace

std::string base64(const std::string& bytes) {
  static constexpr char kAlphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((bytes.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned v = (unsigned(std::uint8_t(bytes[i])) << 16) | (unsigned(std::uint8_t(bytes[i + 1])) << 8) |
                       unsigned(std::uint8_t(bytes[i + 2]));
    for (const int shift : {18, 12, 6, 0}) out += kAlphabet[(v >> shift) & 63];
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned v = (unsigned(std::uint8_t(bytes[i])) << 16) | (two ? unsigned(std::uint8_t(bytes[i + 1])) << 8 : 0);
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += two ? kAlphabet[(v >> 6) & 63] : '=';
    out += '=';
  }
  return out;
}

std::string report_html(const json& report, const std::string& preview_png) {
  const json& design = at(report, "design");
  const json& surface = at(report, "surface");
  const json& verdict = at(report, "verdict");
  const std::string units = at(design, "units").is_string() ? at(design, "units").get<std::string>() : "mm";
  std::string html =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>Paver report</title>\n"
      "<style>body{font-family:sans-serif;max-width:52em;margin:2em auto;color:#222}"
      "table{border-collapse:collapse;margin:.5em 0 1.2em}td,th{border:1px solid #bbb;padding:.25em .6em;"
      "text-align:right}th{background:#eee}td:first-child,th:first-child{text-align:left}"
      ".ok{color:#176b2c}.bad{color:#a11}img{max-width:100%;border:1px solid #ccc}"
      "@media print{body{margin:0}h2{page-break-after:avoid}}</style></head><body>\n";
  html += "<h1>Paver report</h1>\n<p>Surface <b>" + text_of(at(surface, "path")) + "</b> (" +
          text_of(at(surface, "faces")) + " faces, area " + text_of(at(surface, "area")) + " " + escaped(units) +
          "&sup2;); design " + text_of(at(design, "source")) + ": " + text_of(at(design, "tessellation")) +
          " pattern, D = " + text_of(at(design, "spacing")) + " " + escaped(units) + ", gap " +
          text_of(at(design, "gap")) + ", margin " + text_of(at(design, "margin")) + ".</p>\n";

  // A band's closure changes D (and, with stones kept, the free space between them): say so beside
  // the design's figures, which are the rule the pavement was checked against.
  const json& band = at(at(report, "pattern"), "band");
  if (band.is_object()) {
    if (at(at(band, "closure"), "text").is_string())
      html += "<p>Band: " + text_of(at(at(band, "closure"), "text")) + ".</p>\n";
    else if (at(band, "annulus_because").is_string())
      html += "<p>Band paved as an annulus: " + text_of(at(band, "annulus_because")) + ".</p>\n";
  }

  // Where the lattice was laid, when the design asked for rows along an axis or a fitted offset:
  // a facade's designer checks the rows and the count it bought.
  const json& aligned = at(at(report, "pattern"), "row_alignment");
  if (aligned.is_object())
    html += "<p>Rows along " + text_of(at(aligned, "axis")) + ": the pattern turned " +
            fixed(at(aligned, "rotation_deg"), 1) + " degrees; the axis meets the surface at " +
            fixed(at(aligned, "axis_to_surface_deg"), 0) + " degrees on average.</p>\n";
  const json& fit = at(at(report, "pattern"), "offset_fit");
  if (fit.is_object()) {
    const json &chosen = at(fit, "chosen"), &own = at(fit, "at_design_offset");
    const bool paved = at(chosen, "kept").is_number();
    html += "<p>Offset fitted: the lattice shifted (" + text_of(at(chosen, "shift_in_cells")[0]) + ", " +
            text_of(at(chosen, "shift_in_cells")[1]) + ") of a cell, " +
            (paved ? text_of(at(chosen, "kept")) + " elements kept against " + text_of(at(own, "kept"))
                   : text_of(at(chosen, "laid_out")) + " laid out against " + text_of(at(own, "laid_out"))) +
            " at the design's offset.</p>\n";
  }

  const bool ok = at(verdict, "ok").is_boolean() && at(verdict, "ok").get<bool>();
  html += std::string("<h2>Verdict: <span class=\"") + (ok ? "ok\">ok" : "bad\">NOT OK") + "</span></h2>\n";
  if (ok) html += "<p>No contact violations, no boundary crossings, pattern intact.</p>\n";
  if (at(verdict, "problems").is_array() && !at(verdict, "problems").empty()) {
    html += "<ul>\n";
    for (const json& problem : at(verdict, "problems")) html += "<li>" + text_of(problem) + "</li>\n";
    html += "</ul>\n";
  }

  if (!preview_png.empty())
    html += "<p><img alt=\"the paved surface\" src=\"data:image/png;base64," + base64(preview_png) + "\"></p>\n";
  else
    html += "<p><i>No picture: run with --png (it needs a Vulkan device, lavapipe will do) to have one here.</i></p>\n";

  const json& stones = at(report, "stones");
  html += "<h2>Bill of stones</h2>\n<table>\n";
  row(html, {"shape", "diameter (mm)", "count", "carat each", "carats"}, true);
  if (at(stones, "rows").is_array())
    for (const json& r : at(stones, "rows"))
      row(html, {text_of(at(r, "shape")),
                 at(r, "diameter_mm").is_number() ? diameter_mm_text(at(r, "diameter_mm").get<double>()) : "&ndash;",
                 text_of(at(r, "count")),
                 carats(at(r, "carat_each"), carat_each_text), carats(at(r, "carat_total"), carat_total_text)});
  row(html, {"<b>total</b>", "", "<b>" + text_of(at(stones, "count")) + "</b>", "",
             "<b>" + carats(at(stones, "carat_total"), carat_total_text) + "</b>"});
  html += "</table>\n<p><small>" + text_of(at(stones, "carat_rule")) + "</small></p>\n";

  const json& beads = at(report, "beads");
  if (at(beads, "enabled").is_boolean() && at(beads, "enabled").get<bool>())
    html += "<p>Beads (shared prongs): <b>" + text_of(at(beads, "count")) + "</b>, " +
            fixed(at(beads, "diameter_mm_min"), 2) + " to " + fixed(at(beads, "diameter_mm_max"), 2) + " mm.</p>\n";

  const json& cut = at(report, "cut");
  if (cut.is_object()) {
    std::string files;
    if (at(cut, "files").is_array())
      for (const json& f : at(cut, "files")) files += (files.empty() ? "" : ", ") + text_of(f);
    html += "<h2>Metal with seats (" + files + ")</h2>\n<p>" + text_of(at(cut, "cutter")) +
            " cutters, metal " + text_of(at(cut, "thickness")) + " " + escaped(units) + " thick: " +
            fixed(at(cut, "volume_mm3"), 1) + " mm&sup3; of " + fixed(at(cut, "shell_volume_mm3"), 1) +
            " mm&sup3; left; a closed, manifold solid.</p>\n<table>\n";
    row(html, {"alloy", "density (g/cm&sup3;)", "weight (g)"}, true);
    if (at(cut, "metal").is_array())
      for (const json& m : at(cut, "metal"))
        row(html, {text_of(at(m, "alloy")), fixed(at(m, "density_g_cm3"), 2), fixed(at(m, "grams"), 2)});
    html += "</table>\n";
  }

  const json& q = at(report, "quality_after");
  html += "<h2>Quality</h2>\n<table>\n";
  row(html, {"figure", "value"}, true);
  row(html, {"elements", text_of(at(q, "elements"))});
  row(html, {"pairs closer than their radii plus the gap", text_of(at(q, "contact_violations"))});
  row(html, {"smallest clearance (" + escaped(units) + ")", text_of(at(q, "min_clearance"))});
  row(html, {"elements crossing the boundary or margin", text_of(at(q, "boundary_crossings"))});
  row(html, {"fill (elements over the ideal count)", fixed(at(q, "fill"), 3)});
  row(html, {"nearest neighbour over diameter, p95", fixed(at(at(q, "neighbor_ratio"), "p95"), 3)});
  row(html, {"interior stones with the lattice's valence", fixed(at(q, "regular_valence_share"), 3)});
  html += "</table>\n<p><small>Written by Paver with report.json, which holds every figure.</small></p>\n";
  html += "</body></html>\n";
  return html;
}

void write_report_html(const std::filesystem::path& folder, const json& report) {
  std::string png;
  const std::filesystem::path preview = folder / "preview.png";
  if (std::filesystem::is_regular_file(preview)) {
    std::ifstream in(preview, std::ios::binary);
    png.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  write_text_atomically(folder / "report.html", report_html(report, png));
}

}  // namespace paver
