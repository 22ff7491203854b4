#pragma once
// Output helpers for chapter 1's example programs. Their output is included in the page
// with \htmlinclude, because Doxygen 1.9.4 does not typeset \f$ formulas in text pulled in
// with \include{doc}. So the programs write HTML whose formulas use MathJax's own
// delimiters, \( \) and \[ \]; MathJax typesets them in the browser with the course macros
// of docs/macros.tex, which Doxygen puts in every page's MathJax configuration.
//
// Text is written with light markup: \f$..\f$ inline and \f[..\f] display formulas (as in
// the chapter pages), **bold** and `code`.
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace ch01_html {

/// A number as the page shows it: `digits` significant digits, no "-0".
inline std::string num(double x, int digits = 6) {
  if (x == 0.0) x = 0.0;  // -0 -> 0
  std::ostringstream out;
  out << std::setprecision(digits) << x;
  return out.str();
}

/// A vector as (a, b, c); components below `zero` in magnitude are shown as 0.
template <typename Derived>
std::string tuple(const Eigen::MatrixBase<Derived>& v, double zero = 5e-16) {
  std::string out = "(";
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    const double x = std::abs(v[i]) < zero ? 0.0 : static_cast<double>(v[i]);
    out += num(x) + (i + 1 < v.size() ? ", " : ")");
  }
  return out;
}

/// A matrix as a LaTeX bmatrix (for use inside a formula).
template <typename Derived>
std::string bmatrix(const Eigen::MatrixBase<Derived>& m, double zero = 5e-16) {
  std::string out = "\\begin{bmatrix} ";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    for (Eigen::Index k = 0; k < m.cols(); ++k) {
      const double x = std::abs(m(i, k)) < zero ? 0.0 : static_cast<double>(m(i, k));
      out += num(x) + (k + 1 < m.cols() ? " & " : "");
    }
    out += i + 1 < m.rows() ? " \\\\ " : " ";
  }
  return out + "\\end{bmatrix}";
}

/// Light markup to HTML: escapes &, <, >; \f$ \f$ -> \( \); \f[ \f] -> \[ \];
/// **x** -> <b>x</b>; `x` -> <code>x</code>.
inline std::string html(const std::string& text) {
  std::string out;
  bool inlineOpen = false, bold = false, code = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    const char next = i + 1 < text.size() ? text[i + 1] : '\0';
    const char after = i + 2 < text.size() ? text[i + 2] : '\0';
    if (c == '\\' && next == 'f' && (after == '$' || after == '[' || after == ']')) {
      if (after == '$') {
        out += inlineOpen ? "\\)" : "\\(";
        inlineOpen = !inlineOpen;
      } else {
        out += after == '[' ? "\\[" : "\\]";
      }
      i += 2;
    } else if (c == '*' && next == '*') {
      out += bold ? "</b>" : "<b>";
      bold = !bold;
      ++i;
    } else if (c == '`') {
      out += code ? "</code>" : "<code>";
      code = !code;
    } else if (c == '&') {
      out += "&amp;";
    } else if (c == '<') {
      out += "&lt;";
    } else if (c == '>') {
      out += "&gt;";
    } else {
      out += c;
    }
  }
  return out;
}

/// A paragraph of marked-up text.
inline std::string paragraph(const std::string& text) { return "<p>" + html(text) + "</p>\n"; }

/// A table styled like Doxygen's Markdown tables; cells are marked-up text.
inline std::string table(const std::vector<std::string>& header,
                         const std::vector<std::vector<std::string>>& rows) {
  std::string out = "<table class=\"markdownTable\">\n<tr class=\"markdownTableHead\">";
  for (const std::string& h : header) out += "<th class=\"markdownTableHeadNone\">" + html(h) + "</th>";
  out += "</tr>\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out += r % 2 == 0 ? "<tr class=\"markdownTableRowOdd\">" : "<tr class=\"markdownTableRowEven\">";
    for (const std::string& cell : rows[r]) {
      out += "<td class=\"markdownTableBodyNone\">" + html(cell) + "</td>";
    }
    out += "</tr>\n";
  }
  return out + "</table>\n";
}

}  // namespace ch01_html
