#pragma once
// The one exception type the engine throws for bad input and invalid state.
// Messages say what was wrong and where ("image 'x.png': truncated at row 12"),
// so a caller can print what() and a user knows what to fix.
#include <stdexcept>
#include <string>

namespace engine {

class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

}  // namespace engine
