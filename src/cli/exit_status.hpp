// appell/src/cli/exit_status.hpp -- one mapping from exceptions to exit statuses for
// every command and front end (SCENES.md; the errors and their statuses: appell/errors.hpp):
// 2 bad input (one line naming the field), 3 no certificate, 4 internal error.
#pragma once

#include <exception>
#include <iostream>
#include <string>
#include <string_view>

#include "appell/errors.hpp"
#include "appell/io/scene.hpp"

namespace appell::cli {

// A message fit for the one-line contract (user text such as an unknown key or
// option is echoed in messages): appell::printable, at most 400 characters.
inline std::string one_line(std::string_view why) { return appell::printable(why, 400); }

/// Call from a catch block only.  `report`: print the one line on stderr (false on
/// the other ranks of a distributed run, which share the status but not the message).
inline int exit_status_of_current_exception(bool report = true) {
  std::ostream& err = std::cerr;
  auto say = [&](const std::string& line) {
    if (report) err << "appell: " << line << "\n";
  };
  try {
    throw;
  } catch (const appell::input_error& e) {
    say(one_line(e.what()));
    return exit_code(exit_status::bad_input);
  } catch (const appell::parse_error& e) {
    say(one_line(e.what()));
    return exit_code(exit_status::bad_input);
  } catch (const appell::certification_error& e) {
    say("cannot certify: " + one_line(e.what()));
    return exit_code(exit_status::no_certificate);
  } catch (const appell::domain_error& e) {
    say("cannot certify: " + one_line(e.what()));
    return exit_code(exit_status::no_certificate);
  } catch (const std::exception& e) {
    say("internal error: " + one_line(e.what()));
    return exit_code(exit_status::internal);
  }
}

}  // namespace appell::cli
