#pragma once
/// \file
/// \brief Small helpers shared by the output writers (chapter 10): opening files with an
/// error that names the path, and formatting numbers exactly or compactly.

#include <string>
#include <vector>

namespace stackbook::output_detail {

/// Write `bytes` to `path` (binary), replacing the file. If the file cannot be opened or
/// written, throws std::runtime_error with the message: the writer's name, then
/// "cannot write", the path in single quotes and the system's reason.
void writeFileOrThrow(const std::string& writer, const std::string& path, const std::string& bytes);

/// The whole file at `path`. If it cannot be opened or read, throws std::runtime_error
/// with the message: the reader's name, then "cannot read", the path in single quotes and
/// the system's reason.
std::string readFileOrThrow(const std::string& reader, const std::string& path);

/// The shortest decimal that reads back as exactly `value` (std::to_chars round trip).
std::string exactDecimal(double value);

/// `value` with at most `decimals` digits after the point, trailing zeros removed
/// ("-0" printed as "0"): for drawing coordinates, where exactness is not needed.
std::string fixedDecimal(double value, int decimals);

/// Standard base64 (RFC 4648, with padding).
std::string base64Encode(const std::string& bytes);

}  // namespace stackbook::output_detail
