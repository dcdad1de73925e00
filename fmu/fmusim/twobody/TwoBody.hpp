// `fmusim twobody`: two rigid bodies coupled through a connector FMU.
#ifndef FMUSIM_TWOBODY_TWOBODY_HPP
#define FMUSIM_TWOBODY_TWOBODY_HPP

#include <string>
#include <vector>

namespace fmusim {

const char* twoBodyUsage();

// args: everything after "twobody". Returns the exit code; throws the
// classes of Errors.hpp.
int twoBodyCommand(const std::vector<std::string>& args);

} // namespace fmusim

#endif
