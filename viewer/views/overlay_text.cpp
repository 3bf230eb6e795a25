// Text over a view (captions, legends, labels, the colour bar): one style. VTK's built-in fonts
// (Arial, Courier, Times) hold Latin letters only: γ, ³, × and θ come out blank; DejaVu Sans
// (Debian's fonts-dejavu-core, which scripts/setup.sh installs) holds them, and text uses it where it is installed.
#include <filesystem>

#include <vtkTextProperty.h>

#include "views/view_parts.hpp"

namespace shadowlab {

void style_overlay_text(vtkTextProperty* text, int size, const glm::dvec3& colour) {
    static const char* const kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    static const bool installed = std::filesystem::exists(kDejaVuSans);
    if (installed) {
        text->SetFontFamily(VTK_FONT_FILE);
        text->SetFontFile(kDejaVuSans);
    }
    text->SetFontSize(size);
    text->SetColor(colour.r, colour.g, colour.b);
    text->SetBackgroundColor(0.0, 0.0, 0.0);
    text->SetBackgroundOpacity(0.55);
}

}  // namespace shadowlab
