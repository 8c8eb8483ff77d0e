#pragma once
// Reading an input file (a CSV file, a scenario, a law file, a part file) within the budget
// (frictionlab/budget.hpp). A regular file is read whole; a pipe or FIFO is read as a stream,
// once; a directory, a character or block device (`/dev/zero`, a link to it named `.csv`) or a
// socket is refused at once, before any byte is read, so no input is read without end. The bytes
// read count against the memory budget: a larger file (or a stream that goes on past it) is
// refused naming the file and the size.

#include <cstddef>
#include <string>

#include "frictionlab/export.hpp"
namespace frictionlab FRICTIONLAB_API {

/// The most bytes one input file may hold: a quarter of the memory budget (a file's text and
/// the numbers parsed from it are in memory together).
double input_byte_limit();

/// Refuses what cannot be an input file, before opening it: a missing path, a directory, a
/// character or block device, a socket (links are followed). `what` names the file's role in
/// the message ("CSV file", "scenario file"); `code` is the InputError's code.
/// \throws InputError(code, file) naming the path and what it is.
void check_input_file(const std::string& path, const std::string& what, const char* code);

/// How long a read of a pipe or FIFO waits for bytes between two polls of the cancellation token
/// (frictionlab/cancellation.hpp): a FIFO that no one writes is waited for, and Ctrl-C in Python
/// stops the wait within this.
inline constexpr int kInputPollMilliseconds = 50;

/// check_input_file(), then opens `path` for reading, without blocking (a FIFO's open returns at
/// once). Returns the descriptor, which the caller closes.
/// \throws InputError(code, file) as check_input_file, or when the file cannot be opened.
int open_input_file(const std::string& path, const std::string& what, const char* code);

/// Reads up to `size` bytes of `fd` (from open_input_file) into `buf`; 0 at the end of the file.
/// Waits for a pipe's or FIFO's writer as long as it takes, polling the cancellation token every
/// kInputPollMilliseconds. \throws Cancelled when the current token is set;
/// InputError(code, file) on a read error.
std::size_t read_input_block(int fd, char* buf, std::size_t size, const std::string& path, const std::string& what,
                             const char* code);

/// check_input_file(), then the file's bytes: a regular file whole, a pipe or FIFO as a stream
/// until its end. \throws InputError(code) when the file cannot be opened or read;
/// InputError(budget.memory, file) when it holds more than input_byte_limit() bytes.
std::string read_input_file(const std::string& path, const std::string& what, const char* code);

}  // namespace frictionlab
