// Render the mathematics that pymdownx.arithmatex (generic mode) marks in every page with the
// KaTeX copy served from this site (assets/katex).
document.addEventListener("DOMContentLoaded", function () {
  document.querySelectorAll(".arithmatex").forEach(function (element) {
    var text = element.textContent.trim();
    var display = element.tagName === "DIV";
    if (display && text.startsWith("\\[") && text.endsWith("\\]")) {
      text = text.slice(2, -2);
    } else if (!display && text.startsWith("\\(") && text.endsWith("\\)")) {
      text = text.slice(2, -2);
    }
    katex.render(text, element, { displayMode: display, throwOnError: false });
  });
});
