#pragma once
// Reading an input file (a CSV file, a scenario, a law file, a part file) within the budget
// (frictionlab/budget.hpp). A regular file is read whole; a pipe or FIFO is read as a stream,
// once; a directory, a character or block device (`/dev/zero`, a link to it named `.csv`) or a
// socket is refused at once, before any byte is read, so no input is read without end. The bytes
// read count against the memory budget: a larger file (or a stream that goes on past it) is
// refused naming the file and the size.

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

/// check_input_file(), then the file's bytes: a regular file whole, a pipe or FIFO as a stream
/// until its end. \throws InputError(code) when the file cannot be opened or read;
/// InputError(budget.memory, file) when it holds more than input_byte_limit() bytes.
std::string read_input_file(const std::string& path, const std::string& what, const char* code);

}  // namespace frictionlab
