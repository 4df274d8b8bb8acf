#pragma once
// Where a design.json key lives in the studio: the panel and the field a designer sees, so that a
// refused change names the field to fix ("Elements > V-elements > s"), not only the file's key.
#include <string>
#include <string_view>

namespace paver::studio {

// "Elements > E-element 0 > t" for "elements.edge[0].t"; empty for a key without a field.
std::string studio_field(std::string_view key);

// `message` with every quoted key ('elements.gap') that has a field written as the field with the
// key after it (Elements > Stones > gap (elements.gap)); other text is kept.
std::string in_studio_words(std::string_view message);

}  // namespace paver::studio
