// Scene files (chapter 10): reading the JSON text of a scene file and applying --set
// overrides to it. See scene.hpp and docs/scene_format.md.
//
// The text is parsed by nlohmann::json's SAX parser (which is iterative, so no nesting
// depth can exhaust the stack) into a handler that builds the document and refuses, with
// the JSON pointer where it happens, what the library would accept or report in its own
// words: nesting beyond the depth limit, a number beyond the range of a double, and a key
// given twice in one object (the library keeps the last one silently).
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "stackbook/scene/scene.hpp"
#include "stackbook/scene/scene_reader.hpp"

namespace stackbook {

using nlohmann::json;

namespace {

/// Why a text is not accepted: a syntax error (at a byte) or a refusal (at a pointer).
struct JsonTextError {
  bool syntax = false;      ///< a syntax error of the JSON grammar
  std::size_t byte = 0;     ///< where the parser stopped (syntax errors)
  std::string pointer;      ///< where in the document (refusals)
  std::string reason;
};

/// The SAX handler: the library's DOM builder, with the refusals above.
class CheckedSax {
 public:
  CheckedSax(json& root, int depthLimit) : dom_(root, false), depthLimit_(depthLimit) {}

  bool null() { return value() && dom_.null(); }
  bool boolean(bool b) { return value() && dom_.boolean(b); }
  bool number_integer(json::number_integer_t x) { return value() && dom_.number_integer(x); }
  bool number_unsigned(json::number_unsigned_t x) { return value() && dom_.number_unsigned(x); }
  bool number_float(json::number_float_t x, const json::string_t& s) { return value() && dom_.number_float(x, s); }
  bool string(json::string_t& s) { return value() && dom_.string(s); }
  bool binary(json::binary_t& b) { return value() && dom_.binary(b); }
  bool start_object(std::size_t n) { return open(true) && dom_.start_object(n); }
  bool end_object() {
    frames_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) { return open(false) && dom_.start_array(n); }
  bool end_array() {
    frames_.pop_back();
    return dom_.end_array();
  }
  bool key(json::string_t& k) {
    Frame& f = frames_.back();
    f.token = scene_detail::escapePointerToken(k);
    if (!f.keys.insert(k).second) {
      return refuse(pointer(), "the key \"" + k + "\" is given twice in this object (JSON keeps only one; remove the other)");
    }
    return dom_.key(k);
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& /*token*/, const Exception& e) {
    if (error_.reason.empty()) {
      if (e.id == 406) {  // out_of_range.406: a number too large for a double
        next();
        error_.pointer = pointer();
        error_.reason = "the number is beyond the range of a double (about 1.8e308)";
      } else {
        error_.syntax = true;
        error_.byte = position;
        std::string what = e.what();
        const auto at = what.find("syntax error");
        error_.reason = at == std::string::npos ? what : what.substr(at);
      }
    }
    return false;
  }
  const JsonTextError& error() const { return error_; }

 private:
  struct Frame {
    bool object = false;
    std::set<std::string> keys;
    std::string token;    // the key or the index of the current child
    long long index = -1;
  };
  /// The next child of an array gets the next index.
  void next() {
    if (!frames_.empty() && !frames_.back().object) frames_.back().token = std::to_string(++frames_.back().index);
  }
  bool value() {
    next();
    return true;
  }
  bool open(bool object) {
    next();
    if (static_cast<int>(frames_.size()) >= depthLimit_) {
      return refuse(pointer(), "nested deeper than " + std::to_string(depthLimit_) +
                                   " levels of arrays and objects (the limit of the scene format)");
    }
    frames_.push_back(Frame{object, {}, {}, -1});
    return true;
  }
  std::string pointer() const {
    std::string out;
    for (const Frame& f : frames_) {
      if (!f.token.empty() || f.object) out += "/" + f.token;
    }
    return out;
  }
  bool refuse(const std::string& at, const std::string& reason) {
    if (error_.reason.empty()) {
      error_.pointer = at;
      error_.reason = reason;
    }
    return false;
  }

  nlohmann::detail::json_sax_dom_parser<json> dom_;
  int depthLimit_;
  std::vector<Frame> frames_;
  JsonTextError error_;
};

/// Parses `text`; false (with `error`) if it is not accepted.
bool parseChecked(const std::string& text, int depthLimit, json& out, JsonTextError& error) {
  CheckedSax sax(out, depthLimit);
  bool ok = false;
  try {
    ok = json::sax_parse(text, &sax, json::input_format_t::json, true, false);
  } catch (const json::exception& e) {  // not expected: the handler does not throw
    error.syntax = true;
    error.reason = e.what();
    return false;
  }
  if (!ok) {
    error = sax.error();
    if (error.reason.empty()) {
      error.syntax = true;
      error.reason = "not valid JSON";
    }
  }
  return ok;
}

/// "line L, column C" of byte `byte` in `text` (1-based).
std::string lineColumn(const std::string& text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t k = 0; k + 1 < byte && k < text.size(); ++k) {
    if (text[k] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// Whether `s` is well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, at most
/// U+10FFFF).
bool validUtf8(const std::string& s) {
  std::size_t k = 0;
  while (k < s.size()) {
    const auto c = static_cast<unsigned char>(s[k]);
    std::size_t n = 0;
    std::uint32_t cp = 0;
    if (c < 0x80) {
      ++k;
      continue;
    } else if (c >= 0xC2 && c <= 0xDF) {
      n = 1;
      cp = c & 0x1F;
    } else if (c >= 0xE0 && c <= 0xEF) {
      n = 2;
      cp = c & 0x0F;
    } else if (c >= 0xF0 && c <= 0xF4) {
      n = 3;
      cp = c & 0x07;
    } else {
      return false;
    }
    for (std::size_t j = 1; j <= n; ++j) {
      if (k + j >= s.size()) return false;
      const auto d = static_cast<unsigned char>(s[k + j]);
      if ((d & 0xC0) != 0x80) return false;
      cp = (cp << 6) | (d & 0x3F);
    }
    if ((n == 2 && cp < 0x800) || (n == 3 && (cp < 0x10000 || cp > 0x10FFFF)) || (cp >= 0xD800 && cp <= 0xDFFF)) {
      return false;
    }
    k += n + 1;
  }
  return true;
}

}  // namespace

std::string whyNotARegularFile(const std::filesystem::path& path) {
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (std::filesystem::is_regular_file(status)) return "";
  if (std::filesystem::is_directory(status)) return "a folder, not a file";
  if (std::filesystem::exists(status)) return "not a regular file (a device, a pipe or a socket)";
  return "no such file";
}

std::string printable(const std::string& text) {
  std::string out;
  std::size_t k = 0;
  const auto hex = [&out](unsigned char c) {
    static const char* digits = "0123456789abcdef";
    out += "\\x";
    out += digits[c >> 4];
    out += digits[c & 15];
  };
  while (k < text.size()) {
    const auto c = static_cast<unsigned char>(text[k]);
    if (c < 0x20 || c == 0x7F) {
      hex(c);
      ++k;
      continue;
    }
    if (c < 0x80) {
      out += static_cast<char>(c);
      ++k;
      continue;
    }
    // The longest valid UTF-8 sequence starting here, else one byte escaped.
    std::size_t n = c >= 0xF0 ? 4 : c >= 0xE0 ? 3 : 2;
    if (k + n <= text.size() && validUtf8(text.substr(k, n))) {
      const std::string seq = text.substr(k, n);
      // C1 control characters (U+0080 to U+009F) are escaped too.
      if (n == 2 && static_cast<unsigned char>(seq[0]) == 0xC2 && static_cast<unsigned char>(seq[1]) < 0xA0) {
        hex(static_cast<unsigned char>(seq[0]));
        hex(static_cast<unsigned char>(seq[1]));
      } else {
        out += seq;
      }
      k += n;
    } else {
      hex(c);
      ++k;
    }
  }
  return out;
}

json parseSceneJsonText(const std::string& text, const std::string& file, const SceneLimits& limits) {
  if (text.size() > limits.fileBytes) {
    throw SceneError(file, "", "the file has " + std::to_string(text.size()) + " bytes; a scene file may have at most " +
                                   std::to_string(limits.fileBytes));
  }
  json doc;
  JsonTextError error;
  if (!parseChecked(text, limits.jsonDepth, doc, error)) {
    if (error.syntax) {
      // NaN and Infinity are what a program that prints doubles writes; JSON has neither.
      std::string hint;
      const std::size_t from = error.byte > 12 ? error.byte - 12 : 0;
      const std::string near = text.substr(from, 24);
      for (const char* word : {"NaN", "nan", "Infinity", "inf"}) {
        const bool badWord = error.reason.find("invalid literal") != std::string::npos ||
                             error.reason.find("invalid number") != std::string::npos;  // -Infinity
        if (badWord && near.find(word) != std::string::npos) {
          hint = "; JSON has no NaN or Infinity: write a finite number";
          break;
        }
      }
      throw SceneError(file, "", lineColumn(text, error.byte) + ": not valid JSON (" + error.reason + ")" + hint);
    }
    throw SceneError(file, error.pointer, error.reason);
  }
  return doc;
}

json readSceneJson(const std::string& path, const SceneLimits& limits) {
  std::error_code ec;
  if (const std::string why = whyNotARegularFile(path); !why.empty()) {
    throw SceneError(path, "", why == "no such file" ? "no such scene file" : "the scene is " + why);
  }
  const auto bytes = std::filesystem::file_size(path, ec);
  if (!ec && bytes > limits.fileBytes) {
    throw SceneError(path, "", "the file has " + std::to_string(bytes) + " bytes; a scene file may have at most " +
                                   std::to_string(limits.fileBytes));
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path, "", "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return parseSceneJsonText(text.str(), path, limits);
}

void applySceneOverride(json& doc, const std::string& keyValue, const std::string& file, const SceneLimits& limits) {
  const auto eq = keyValue.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw SceneError(file, "", "--set expects key=value (e.g. dt=0.0005), got \"" + keyValue + "\"");
  }
  std::string key = keyValue.substr(0, eq);
  const std::string text = keyValue.substr(eq + 1);
  std::replace(key.begin(), key.end(), '.', '/');
  if (key.front() != '/') key.insert(key.begin(), '/');
  if (!validUtf8(key)) throw SceneError(file, key, "--set: the key is not valid UTF-8");
  // The reference tokens of the key (RFC 6901: "~0" is "~" and "~1" is "/").
  std::vector<std::string> tokens;
  for (std::size_t start = 1;;) {
    const std::size_t end = key.find('/', start);
    std::string raw = key.substr(start, end == std::string::npos ? std::string::npos : end - start);
    std::string token;
    for (std::size_t k = 0; k < raw.size(); ++k) {
      if (raw[k] != '~') {
        token += raw[k];
      } else if (k + 1 < raw.size() && (raw[k + 1] == '0' || raw[k + 1] == '1')) {
        token += raw[++k] == '0' ? '~' : '/';
      } else {
        throw SceneError(file, key, "--set: in a key, \"~\" must be followed by 0 (for ~) or 1 (for /)");
      }
    }
    tokens.push_back(std::move(token));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  json value;
  JsonTextError error;
  if (!parseChecked(text, limits.jsonDepth, value, error)) {
    if (!error.syntax) {
      throw SceneError(file, key, "--set value" + (error.pointer.empty() ? "" : " at " + error.pointer) + ": " +
                                      error.reason);
    }
    // A bare word: a string, e.g. --set solver.order=traditional.
    if (!validUtf8(text)) throw SceneError(file, key, "--set: the value is not valid UTF-8 (nor JSON)");
    value = text;
  }
  // Walk the document: objects gain missing members, an array index may be at most the
  // array's size (which appends), and nothing else can hold a field.
  json* at = &doc;
  std::string walked;
  for (const std::string& token : tokens) {
    const std::string here = walked + "/" + scene_detail::escapePointerToken(token);
    if (at->is_null()) *at = json::object();
    if (at->is_object()) {
      at = &(*at)[token];
    } else if (at->is_array()) {
      const bool digits = !token.empty() && token.size() <= 18 &&
                          std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; }) &&
                          (token.size() == 1 || token[0] != '0');
      if (!digits) {
        throw SceneError(file, here, "--set: " + (walked.empty() ? std::string("the document") : walked) +
                                         " is an array; expected an index 0 to " + std::to_string(at->size()) +
                                         ", got \"" + token + "\"");
      }
      const auto index = std::stoull(token);
      if (index > at->size()) {
        throw SceneError(file, here, "--set: index " + token + " is beyond the end of " +
                                         (walked.empty() ? std::string("the document") : walked) + " (an array of " +
                                         std::to_string(at->size()) + " elements; index " +
                                         std::to_string(at->size()) + " appends)");
      }
      if (index == at->size()) at->push_back(json());
      at = &(*at)[static_cast<std::size_t>(index)];
    } else {
      throw SceneError(file, here, "--set: " + (walked.empty() ? std::string("the document") : walked) + " is " +
                                       scene_detail::describeValue(*at) + ", which has no fields");
    }
    walked = here;
  }
  *at = std::move(value);
}

}  // namespace stackbook
