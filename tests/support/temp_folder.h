#pragma once

// A fresh folder under the system's temporary folder for the files a test writes, removed
// with everything in it when the object goes (a static one: at the end of the run).

#include <filesystem>
#include <string>

namespace shadowgen::test {

class TempFolder {
 public:
  explicit TempFolder(const std::string& prefix);  // "<tmp>/<prefix>-XXXXXX"
  ~TempFolder();
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  const std::filesystem::path& path() const { return path_; }

  // Writes `content` to `name` in the folder (byte for byte); returns the file's path.
  std::filesystem::path write(const std::string& name, const std::string& content) const;

 private:
  std::filesystem::path path_;
};

}  // namespace shadowgen::test
