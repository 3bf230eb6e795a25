// ?selftest: clicks every step button in turn and records which step each click shows and what
// each of its canvases drew (pixels other than the background), then the errors met, as JSON in
// <pre id="selftest">, which headless Chromium's --dump-dom prints (tests/interactive_lesson_test.py).
export function runSelfTest(buttons, sections, shownViews, errors, out) {
  const steps = buttons.map((button) => {
    button.click();
    return {
      button: button.dataset.step,
      shown: sections.filter((section) => !section.hidden).map((section) => section.dataset.step),
      canvases: shownViews().map((view) => view.drawnPixels()),
    };
  });
  out.textContent = JSON.stringify({ steps, errors });
}
