#include "io/atomic_file.h"

#include "core/input_error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace paver {
namespace {

class AtomicFile : public testing::Test {
protected:
  void SetUp() override {
    folder_ = std::filesystem::temp_directory_path() /
              ("paver_atomic_file_" + std::string(testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(folder_);
    std::filesystem::create_directories(folder_);
  }
  void TearDown() override { std::filesystem::remove_all(folder_); }

  std::vector<std::string> names() const {
    std::vector<std::string> result;
    for (const auto& entry : std::filesystem::directory_iterator(folder_))
      result.push_back(entry.path().filename().string());
    return result;
  }

  static std::string read(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  }

  std::filesystem::path folder_;
};

TEST_F(AtomicFile, WritesTheTextAndLeavesNoTemporaryFile) {
  const auto path = folder_ / "report.json";
  write_text_atomically(path, "{\"ok\": true}\n");
  EXPECT_EQ(read(path), "{\"ok\": true}\n");
  EXPECT_EQ(names(), std::vector<std::string>{"report.json"});
}

TEST_F(AtomicFile, KeepsBytesExactly) {
  const auto path = folder_ / "bytes.bin";
  const std::string bytes("a\r\n\0b\n\xff", 7);
  write_file_atomically(path, [&](std::ostream& out) { out.write(bytes.data(), 7); });
  EXPECT_EQ(read(path), bytes);
}

TEST_F(AtomicFile, ReplacesAnExistingFile) {
  const auto path = folder_ / "out.csv";
  write_text_atomically(path, "a much longer old content\n");
  write_text_atomically(path, "new\n");
  EXPECT_EQ(read(path), "new\n");
  EXPECT_EQ(names(), std::vector<std::string>{"out.csv"});
}

TEST_F(AtomicFile, MissingFolderThrowsNamingThePath) {
  const auto path = folder_ / "missing" / "report.json";
  try {
    write_text_atomically(path, "x");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(names().empty()) << "a folder or a temporary file was left behind";
}

TEST_F(AtomicFile, FailingWriterLeavesTheOldFileAndNoTemporaryFile) {
  const auto path = folder_ / "keep.txt";
  write_text_atomically(path, "keep\n");
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out) {
                                       out << "partial";
                                       throw std::runtime_error("writer failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read(path), "keep\n");
  EXPECT_EQ(names(), std::vector<std::string>{"keep.txt"});
}

TEST_F(AtomicFile, BadStreamThrowsInputErrorAndLeavesNoTemporaryFile) {
  const auto path = folder_ / "bad.txt";
  try {
    write_file_atomically(path, [](std::ostream& out) { out.setstate(std::ios::badbit); });
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
  EXPECT_TRUE(names().empty());
}

TEST_F(AtomicFile, TargetThatIsAFolderThrows) {
  const auto path = folder_ / "taken";
  std::filesystem::create_directory(path);
  EXPECT_THROW(write_text_atomically(path, "x"), InputError);
  EXPECT_EQ(names(), std::vector<std::string>{"taken"});
}

}  // namespace
}  // namespace paver
