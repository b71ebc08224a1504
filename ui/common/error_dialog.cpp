#include "ui/common/error_dialog.hpp"

#include <QMessageBox>

namespace clm3d::ui {

void showError(QWidget* parent, const QString& what, const QString& message) {
  QMessageBox box(QMessageBox::Warning, what, what, QMessageBox::Ok, parent);
  box.setObjectName("errorDialog");
  box.setInformativeText(message);
  box.exec();
}

QString messageOf(std::exception_ptr error) {
  try {
    if (error) std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return QString::fromStdString(e.what());
  } catch (...) {
  }
  return QStringLiteral("unknown error");
}

}  // namespace clm3d::ui
