#pragma once
// Nothing a user wrote is ever overwritten: outputs that would land on an input are refused.
#include <filesystem>
#include <vector>

namespace paver {

// Throws InputError when any output path names the same file as any input path.
void refuse_overwriting_inputs(const std::vector<std::filesystem::path>& inputs,
                               const std::vector<std::filesystem::path>& outputs);

// Checks, without writing anything, that `folder` is (or can be made as) a folder we can write
// in: it or its nearest existing parent is a directory with write permission. Throws InputError
// naming the folder and the problem. Called before the expensive work.
void check_output_folder(const std::filesystem::path& folder);

// Checks, without writing anything, that one output file can be written at `path` by renaming a
// new file over it: its folder exists and is writable, and `path` is a regular file or nothing. A
// device, a pipe, a symbolic link or a folder there is refused (renaming over /dev/null made it a
// regular file; over a link, it broke the link instead of writing where it points). Throws
// InputError naming the path. Called before the expensive work, and again by the atomic writer.
void check_output_file(const std::filesystem::path& path);

// Creates the output folder (and parents); throws InputError naming it on failure.
void make_output_folder(const std::filesystem::path& folder);

}  // namespace paver
