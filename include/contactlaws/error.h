// Copyright contactlaws authors.
//
// The one exception type of the library: a one-line message that names the
// file, the tag, the key and the value, e.g.
//   "ball.xml: contactlaw:ball-floor: restitution=1.5 must be in [0, 1]".

#ifndef CONTACTLAWS_ERROR_H_
#define CONTACTLAWS_ERROR_H_

#include <stdexcept>
#include <string>

namespace contactlaws {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace contactlaws

#endif  // CONTACTLAWS_ERROR_H_
