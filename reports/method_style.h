#pragma once
// How each method looks in every figure and table, from the table of methods
// (control/methods.h). A method it does not know (a Python controller's, or one of another
// version) is labelled by its name and coloured by it: a colour no method of the table has,
// chosen by a hash of the name, so it is the same in every report (two such methods may
// share one in 1 of 6 cases).
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "records/batch_folder.h"

namespace camcov::reports {

struct MethodStyle {
  std::string_view label;  // for legends and table headers
  std::string_view color;  // CSS colour
};

MethodStyle methodStyle(std::string_view method);

// While it lives, methodStyle on this thread also knows the methods a batch brought and
// described (records::BatchManifest::methodLooks): a report shows a Python controller by its
// own description and colour.
class BroughtMethodLooks {
 public:
  explicit BroughtMethodLooks(const std::map<std::string, records::MethodLook>& looks);
  ~BroughtMethodLooks();
  BroughtMethodLooks(const BroughtMethodLooks&) = delete;
  BroughtMethodLooks& operator=(const BroughtMethodLooks&) = delete;

 private:
  const std::map<std::string, records::MethodLook>* previous_;
};
// A method's colour dot before `html` (its name or label, escaped), the two kept on one line:
// a narrow column or legend wraps before the dot, never between the dot and the name.
std::string methodMark(std::string_view color, std::string_view html);

}  // namespace camcov::reports
