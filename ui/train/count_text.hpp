// "1 head" / "6 heads": counts in the page's English texts (the studio ships no translations, so
// Qt's %n plural forms would print "head(s)").
#pragma once

#include <QString>

namespace clm3d::ui {

inline QString countText(long long n, const QString& one, const QString& many) {
  return QString("%1 %2").arg(n).arg(n == 1 ? one : many);
}

}  // namespace clm3d::ui
