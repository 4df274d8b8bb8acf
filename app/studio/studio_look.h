#pragma once
// How the studio looks (issue 45: it looked like a research tool): a proportional font (Debian's
// DejaVu Sans, from fonts-dejavu-core) at a size read at arm's length, and a dark graphite theme
// with one blue accent, enough contrast between text, fields and frames, rounded frames.
// Before ImGui builds its font atlas; without the font file ImGui's own font is kept.
namespace paver::studio {

// Path of the proportional font the studio loads (empty when it is not installed).
const char* studio_font_path();

// Loads the font and sets the theme on the current ImGui context; false when the font was missing.
bool apply_studio_look();

}  // namespace paver::studio
