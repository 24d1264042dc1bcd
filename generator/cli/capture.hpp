/** @file capture.hpp  std::cout and std::cerr into strings while a Capture lives: a driver's report kept for a
 * document (eomgen report) or dropped (the members of an animated ensemble). */
#pragma once

#include <iostream>
#include <sstream>
#include <string>

namespace eomgen::cli {

class Capture {
  public:
    Capture() : out_(std::cout.rdbuf(out_text_.rdbuf())), err_(std::cerr.rdbuf(err_text_.rdbuf())) {}
    ~Capture() {
        std::cout.rdbuf(out_);
        std::cerr.rdbuf(err_);
    }
    Capture(const Capture&) = delete;
    Capture& operator=(const Capture&) = delete;
    std::string out() const { return out_text_.str(); }
    std::string err() const { return err_text_.str(); }

  private:
    std::ostringstream out_text_, err_text_;
    std::streambuf *out_, *err_;
};

}  // namespace eomgen::cli
