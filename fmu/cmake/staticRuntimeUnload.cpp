// Linked into every connector FMU binary (fmu/cmake/ConnectorFmu.cmake),
// which carries its own copy of libstdc++ (-static-libstdc++).
//
// libstdc++ keeps an emergency pool for throwing exceptions when malloc
// fails: 72704 bytes taken with malloc when the library starts, never
// given back. With a shared libstdc++ that is once per process; an FMU's
// copy takes a new pool every time the host loads the FMU, and the host's
// dlclose unmaps the only pointer to it, so every load and unload of an
// FMU leaked 71 KB of the host's heap (LeakSanitizer reports it as a
// direct leak from an unloaded module). __gnu_cxx::__freeres() is the
// function libstdc++ provides to free that pool (valgrind calls it at
// exit); this destructor calls it when the FMU is unloaded. It runs before
// the FMU's static objects are destroyed, none of which throws.
namespace __gnu_cxx {
void __freeres();
}

namespace {

__attribute__((destructor)) void freeStaticRuntime()
{
    __gnu_cxx::__freeres();
}

} // namespace
