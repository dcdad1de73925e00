// Removal of a directory tree that is safe in a signal handler.
#ifndef FMUIMPORT_REMOVETREE_HPP
#define FMUIMPORT_REMOVETREE_HPP

namespace fmuImport {

// Removes path and everything below it, without following symbolic links,
// using only open, openat, getdents64, lseek, unlinkat, rmdir and close,
// which are async-signal-safe (getdents64 is a raw system call): no malloc,
// no locks, a small fixed stack. Gives up quietly on what it cannot remove,
// and on trees deeper than 32 levels.
void removeTreeSignalSafe(const char* path) noexcept;

} // namespace fmuImport

#endif
