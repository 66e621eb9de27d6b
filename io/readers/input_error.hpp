// The error every reader throws for bad input: the file, the line (0 when it does not apply)
// and what is wrong. what() is "file:line: message" (or "file: message").
#pragma once

#include <stdexcept>
#include <string>

namespace hlr {

class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string message)
      : std::runtime_error(format(file, line, message)),
        file_(std::move(file)),
        line_(line),
        message_(std::move(message)) {}
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& f, int line, const std::string& m) {
    return line > 0 ? f + ":" + std::to_string(line) + ": " + m : f + ": " + m;
  }
  std::string file_;
  int line_;
  std::string message_;
};

}  // namespace hlr
