#include "ui/shell/standard_pages.hpp"

#include "ui/common/page.hpp"
#if defined(CLM3D_STUDIO_HAS_ANNOTATE) && CLM3D_STUDIO_HAS_ANNOTATE
#include "ui/annotate/annotate_page.hpp"
#endif
#if defined(CLM3D_STUDIO_HAS_TRAIN) && CLM3D_STUDIO_HAS_TRAIN
#include "ui/train/train_page.hpp"
#endif
#if defined(CLM3D_STUDIO_HAS_TRACK) && CLM3D_STUDIO_HAS_TRACK
#include "ui/track/track_page.hpp"
#endif
#if defined(CLM3D_STUDIO_HAS_EVALUATE) && CLM3D_STUDIO_HAS_EVALUATE
#include "ui/evaluate/evaluate_page.hpp"
#endif

namespace clm3d::ui {

QList<Page*> makeStandardPages([[maybe_unused]] QWidget* parent) {
  QList<Page*> pages;
#if defined(CLM3D_STUDIO_HAS_ANNOTATE) && CLM3D_STUDIO_HAS_ANNOTATE
  pages.append(new AnnotatePage(parent));
#endif
#if defined(CLM3D_STUDIO_HAS_TRAIN) && CLM3D_STUDIO_HAS_TRAIN
  pages.append(new TrainPage(parent));
#endif
#if defined(CLM3D_STUDIO_HAS_TRACK) && CLM3D_STUDIO_HAS_TRACK
  pages.append(new TrackPage(parent));
#endif
#if defined(CLM3D_STUDIO_HAS_EVALUATE) && CLM3D_STUDIO_HAS_EVALUATE
  pages.append(new EvaluatePage(parent));
#endif
  return pages;
}

}  // namespace clm3d::ui
