#include "detail/idf_text.h"

#include "shadowgen/model/input_error.h"

namespace shadowgen::energyplus::detail {
namespace {

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f'; }

class Splitter {
 public:
  Splitter(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  std::vector<IdfObject> run() {
    for (std::size_t i = 0; i < text_.size(); ++i) {
      const char c = text_[i];
      if (c == '\0') {
        throw InputError(file_, "",
                         "line " + std::to_string(line_) + ": a NUL byte: this is not IDF text");
      }
      if (c == '!') {
        while (i + 1 < text_.size() && text_[i + 1] != '\n') ++i;
        continue;
      }
      if (c == ',' || c == ';') {
        end_field();
        if (c == ';') end_object();
        continue;
      }
      if (c == '\n') ++line_;
      if (blank(c)) {
        if (!field_.text.empty()) pending_blanks_.push_back(c);
        continue;
      }
      if (field_.text.empty()) {
        field_.line = line_;
        if (object_.fields.empty()) object_line_ = line_;
      }
      field_.text += pending_blanks_;
      pending_blanks_.clear();
      field_.text += c;
    }
    if (!object_.fields.empty() || !field_.text.empty()) {
      throw InputError(file_, "",
                       "line " + std::to_string(object_line_) +
                           ": the file ends inside this object: an IDF object ends with ';'");
    }
    return std::move(objects_);
  }

 private:
  void end_field() {
    if (field_.text.empty()) field_.line = line_;
    if (object_.fields.empty()) object_line_ = field_.line;
    object_.fields.push_back(std::move(field_));
    field_ = {};
    pending_blanks_.clear();
  }
  void end_object() {
    // A lone ';' (an empty object) says nothing; it is passed over.
    if (!(object_.fields.size() == 1 && object_.fields[0].text.empty())) {
      objects_.push_back(std::move(object_));
    }
    object_ = {};
  }

  std::string_view text_;
  const std::string& file_;
  std::size_t line_ = 1;
  std::size_t object_line_ = 1;
  IdfField field_;
  std::string pending_blanks_;  // blanks inside a field, kept once text follows them
  IdfObject object_;
  std::vector<IdfObject> objects_;
};

}  // namespace

std::vector<IdfObject> split_idf(std::string_view text, const std::string& file) {
  return Splitter(text, file).run();
}

}  // namespace shadowgen::energyplus::detail
