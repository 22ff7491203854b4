#pragma once
/// \file
/// \brief Comma-separated values as RFC 4180 writes them (chapter 10): the one field
/// quoting rule every CSV output uses, and the reader that reads those files back.

#include <string>
#include <vector>

namespace stackbook {

/// `text` as one CSV field: unchanged when it holds no comma, quote or line end, else
/// wrapped in double quotes with every inner quote doubled (RFC 4180, section 2).
std::string csvField(const std::string& text);

/// The records of a CSV text, each a list of fields, with the quoting of csvField undone.
/// A record ends at a line feed outside quotes; a last line without its line feed is a
/// record cut short (a file still being written) and is not returned.
std::vector<std::vector<std::string>> csvRecords(const std::string& text);

}  // namespace stackbook
