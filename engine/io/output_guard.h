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

// Creates the output folder (and parents); throws InputError naming it on failure.
void make_output_folder(const std::filesystem::path& folder);

}  // namespace paver
