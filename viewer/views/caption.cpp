// A view's caption: bottom-left on a translucent backing, wrapped to the renderer's width in pixels
// each time the renderer starts a render (a panel's width changes when the window is resized), so
// that no caption runs off its panel, in the window or in an exported PNG.
#include <string>
#include <vector>

#include <vtkCommand.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTextRenderer.h>

#include "views/view_parts.hpp"

namespace shadowlab {
namespace {

constexpr int kMargin = 8;  // pixels between the caption and the renderer's edges

// The words of one line, each with the space after it, so that joining them gives the line back:
// a line may break after any space, so after "; " and ", " too.
std::vector<std::string> words_of(const std::string& line) {
    std::vector<std::string> words;
    size_t start = 0;
    while (start < line.size()) {
        const size_t space = line.find(' ', start);
        const size_t end = space == std::string::npos ? line.size() : space + 1;
        words.push_back(line.substr(start, end - start));
        start = end;
    }
    return words;
}

std::string without_trailing_space(std::string text) {
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text;
}

// Greedy wrapping, as a typesetter fills a ragged-right paragraph: each line takes words while its
// measured width fits; a word wider than the whole width gets a line of its own. Explicit newlines stay.
class CaptionWrapper : public vtkCommand {
public:
    static CaptionWrapper* New() { return new CaptionWrapper; }
    std::string text;
    vtkSmartPointer<vtkTextActor> caption;

    void Execute(vtkObject* caller, unsigned long, void*) override {
        auto* renderer = static_cast<vtkRenderer*>(caller);
        const int width = renderer->GetSize()[0] - 2 * kMargin;
        const int dpi = renderer->GetRenderWindow() ? renderer->GetRenderWindow()->GetDPI() : 72;
        const std::string wrapped = wrap(width, dpi);
        if (wrapped != caption->GetInput()) caption->SetInput(wrapped.c_str());
    }

private:
    int measured_width(const std::string& line, int dpi) const {
        int box[4] = {0, 0, 0, 0};
        vtkTextRenderer::GetInstance()->GetBoundingBox(caption->GetTextProperty(), line, box, dpi);
        return box[1] - box[0] + 1;
    }

    std::string wrap(int width, int dpi) const {
        std::string out;
        size_t start = 0;
        while (start <= text.size()) {
            const size_t newline = text.find('\n', start);
            const size_t end = newline == std::string::npos ? text.size() : newline;
            std::string line;
            for (const std::string& word : words_of(text.substr(start, end - start))) {
                if (!line.empty() && measured_width(without_trailing_space(line + word), dpi) > width) {
                    out += without_trailing_space(line) + "\n";
                    line.clear();
                }
                line += word;
            }
            out += without_trailing_space(line);
            if (newline == std::string::npos) break;
            out += "\n";
            start = newline + 1;
        }
        return out;
    }
};

}  // namespace

void add_caption(vtkRenderer* renderer, const std::string& text) {
    vtkNew<vtkTextActor> caption;
    caption->SetInput(text.c_str());
    vtkTextProperty* style = caption->GetTextProperty();
    style_overlay_text(style, 13);
    style->SetJustificationToLeft();
    style->SetVerticalJustificationToBottom();
    caption->SetDisplayPosition(kMargin, kMargin);
    renderer->AddViewProp(caption);
    vtkNew<CaptionWrapper> wrapper;
    wrapper->text = text;
    wrapper->caption = caption;
    renderer->AddObserver(vtkCommand::StartEvent, wrapper);
}

}  // namespace shadowlab
