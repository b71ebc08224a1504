// How the studio reports a failed action: a modal dialog with the core's message (which names the
// file and the problem), so a bad file opened from the GUI never goes unexplained.
#pragma once

#include <QString>
#include <exception>

class QWidget;

namespace clm3d::ui {

// Shows `what` failed, with the message; the dialog's object name is "errorDialog" for tests.
void showError(QWidget* parent, const QString& what, const QString& message);
// The message of an exception (std::exception::what, or a fixed text for anything else).
QString messageOf(std::exception_ptr error);

// Runs action; on an exception shows the error dialog and returns false.
template <typename Action>
bool runReportingErrors(QWidget* parent, const QString& what, Action&& action) {
  try {
    action();
    return true;
  } catch (...) {
    showError(parent, what, messageOf(std::current_exception()));
    return false;
  }
}

}  // namespace clm3d::ui
