#include "ui/train/settings_form.hpp"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QRegularExpressionValidator>
#include <QSpinBox>
#include <QVBoxLayout>
#include <algorithm>
#include <thread>

#include "core/common/error.hpp"

namespace clm3d::ui {
namespace {

QSpinBox* intField(const char* name, int lo, int hi, const QString& tip) {
  auto* box = new QSpinBox;
  box->setObjectName(name);
  box->setRange(lo, hi);
  box->setToolTip(tip);
  return box;
}

QDoubleSpinBox* realField(const char* name, double lo, double hi, double step, int decimals,
                          const QString& tip) {
  auto* box = new QDoubleSpinBox;
  box->setObjectName(name);
  box->setRange(lo, hi);
  box->setSingleStep(step);
  box->setDecimals(decimals);
  box->setToolTip(tip);
  return box;
}

QCheckBox* flagField(const char* name, const QString& text, const QString& tip) {
  auto* box = new QCheckBox(text);
  box->setObjectName(name);
  box->setToolTip(tip);
  return box;
}

QLineEdit* textField(const char* name, const QString& tip) {
  auto* edit = new QLineEdit;
  edit->setObjectName(name);
  edit->setToolTip(tip);
  return edit;
}

// A group box holding a form; rows are (label, field) with the field's tooltip on the label too.
QFormLayout* addGroup(QVBoxLayout* column, const QString& title) {
  auto* group = new QGroupBox(title);
  auto* form = new QFormLayout(group);
  form->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
  column->addWidget(group);
  return form;
}

void addRow(QFormLayout* form, const QString& label, QWidget* field) {
  form->addRow(label, field);
  if (QWidget* labelWidget = form->labelForField(field)) labelWidget->setToolTip(field->toolTip());
}

}  // namespace

std::vector<double> parseAngleList(const QString& text, const std::string& field) {
  std::vector<double> values;
  for (const QString& part : text.split(',', Qt::SkipEmptyParts)) {
    bool ok = false;
    const double value = part.trimmed().toDouble(&ok);
    if (!ok) {
      throw InputError("training settings: " + field + ": '" + part.trimmed().toStdString() +
                       "' is not a number (write degrees separated by commas, e.g. -30, 0, 30)");
    }
    values.push_back(value);
  }
  if (values.empty()) throw InputError("training settings: " + field + ": no angle given");
  return values;
}

QString formatAngleList(const std::vector<double>& values) {
  QStringList parts;
  for (double value : values) parts << QString::number(value);
  return parts.join(", ");
}

SettingsForm::SettingsForm(QWidget* parent) : QWidget(parent) {
  // Two columns: views and patches, then the PCA, perturbations and run settings.
  auto* columns = new QHBoxLayout(this);
  columns->setContentsMargins(0, 0, 0, 0);
  auto* column = new QVBoxLayout;
  auto* secondColumn = new QVBoxLayout;
  columns->addLayout(column);
  columns->addLayout(secondColumn);

  QFormLayout* views = addGroup(column, tr("Views"));
  yaws_ = textField("viewYaws",
                    tr("Yaw centres of the views in degrees (left/right head turn, within +-90), "
                       "separated by commas. Each pitch x yaw pair is one view of the model."));
  pitches_ = textField("viewPitches",
                       tr("Pitch centres of the views in degrees (head up/down, within +-60), "
                          "separated by commas."));
  singleView_ = flagField(
      "singleView", tr("Single-view 2D baseline"),
      tr("Train the single-view 2D baseline instead: one frontal view and a 2D shape model "
         "(the view lists are then ignored)."));
  mirrorRightViews_ = flagField(
      "mirrorRightViews", tr("Mirror right-side views"),
      tr("Build the views with yaw > 0 by mirroring the yaw < 0 ones (half the rendering); off: "
         "render them as well."));
  addRow(views, tr("Yaws (deg)"), yaws_);
  addRow(views, tr("Pitches (deg)"), pitches_);
  views->addRow(singleView_);
  views->addRow(mirrorRightViews_);

  QFormLayout* patches = addGroup(column, tr("Patches"));
  scales_ = intField("scales", 1, 5,
                     tr("Pyramid scales per view (1-5): scale s samples the image at 1/2^s; "
                        "coarse scales widen the search, the finest gives the accuracy."));
  patchSize_ = intField("patchSize", 4, 64,
                        tr("Side of the square patch around each landmark, in pixels, at every "
                           "scale (4-64). Larger patches see more context and train slower."));
  patchRatio_ = realField(
      "patchRatio", 0.05, 1.0, 0.01, 3,
      tr("Patch size / inter-ocular distance at the finest scale (0.05-1): fixes how large the "
         "face is rendered, so a smaller ratio means a larger face and finer detail."));
  samplesPerView_ = intField("samplesPerView", 1, 100,
                             tr("Perturbed renders per subject and view (1-100); more samples "
                                "give the patch PCA more variation and take longer."));
  hiddenShare_ = realField(
      "hiddenShare", 0.0, 1.0, 0.05, 2,
      tr("A landmark hidden in more than this share of a view's renders is left out of the view "
         "(1 keeps every landmark: hidden-point removal off)."));
  supersample_ = intField("supersample", 1, 4,
                          tr("Anti-aliasing of the training renders: each pixel is the mean of "
                             "n x n samples (1-4)."));
  addRow(patches, tr("Scales"), scales_);
  addRow(patches, tr("Patch size (px)"), patchSize_);
  addRow(patches, tr("Patch / eye distance"), patchRatio_);
  addRow(patches, tr("Samples per view"), samplesPerView_);
  addRow(patches, tr("Hidden share"), hiddenShare_);
  addRow(patches, tr("Supersampling"), supersample_);

  column->addStretch(1);
  QFormLayout* pca = addGroup(secondColumn, tr("Variance kept"));
  textureVariance_ = realField(
      "textureVariance", 0.01, 1.0, 0.01, 3,
      tr("Share of the variance each view/scale patch PCA keeps (0.01-1); higher keeps more "
         "texture modes."));
  textureMaxModes_ = intField("textureMaxModes", 0, 1000,
                              tr("At most this many modes per patch PCA (0 = no cap); a cap "
                                 "makes smaller, faster models."));
  shapeVariance_ = realField("shapeVariance", 0.01, 1.0, 0.01, 3,
                             tr("Share of the shape variance the 3D shape model keeps (0.01-1)."));
  shapeMaxModes_ =
      intField("shapeMaxModes", 0, 1000, tr("At most this many shape modes (0 = no cap)."));
  shapeLimit_ = realField("shapeLimit", 0.5, 10.0, 0.5, 1,
                          tr("The fitter keeps each shape parameter b_s within this many "
                             "standard deviations (0.5-10)."));
  mirrorShapes_ = flagField(
      "mirrorShapes", tr("Mirror training shapes"),
      tr("Also train the shape model on a left/right mirrored copy of every training shape."));
  addRow(pca, tr("Texture variance"), textureVariance_);
  addRow(pca, tr("Texture max modes"), textureMaxModes_);
  addRow(pca, tr("Shape variance"), shapeVariance_);
  addRow(pca, tr("Shape max modes"), shapeMaxModes_);
  addRow(pca, tr("Shape limit (SD)"), shapeLimit_);
  pca->addRow(mirrorShapes_);

  QFormLayout* jitter = addGroup(secondColumn, tr("Perturbations (+-range)"));
  rotation_ = realField("rotationJitter", 0, 20, 0.5, 1,
                        tr("Pitch, yaw and roll jitter of each render around its view centre, in "
                           "degrees (0-20)."));
  viewCoverage_ = realField(
      "viewCoverage", 0, 1.5, 0.1, 2,
      tr("Widens the pitch/yaw jitter to this share of half the distance to the nearest other "
         "view centre (never below the rotation), so each view's patches cover the poses the "
         "search uses the view for (0-1.5; 0 = the rotation jitter only)."));
  scaleJitter_ = realField("scaleJitter", 0, 0.3, 0.01, 3,
                           tr("Relative face size jitter (0-0.3; 0.05 = +-5 %)."));
  shift_ = realField("shiftJitter", 0, 4, 0.1, 2,
                     tr("Sub-pixel shift of the face at the finest scale, in pixels (0-4)."));
  light_ = realField("lightJitter", 0, 1, 0.05, 2,
                     tr("Jitter of each component of the light direction (0-1)."));
  ambient_ = realField("ambientJitter", 0, 0.4, 0.05, 2,
                       tr("Jitter of the ambient light term (0-0.4; the term is 0.45)."));
  diffuse_ = realField("diffuseJitter", 0, 0.6, 0.05, 2,
                       tr("Jitter of the diffuse light term (0-0.6; the term is 0.65)."));
  addRow(jitter, tr("Rotation (deg)"), rotation_);
  addRow(jitter, tr("View coverage"), viewCoverage_);
  addRow(jitter, tr("Scale"), scaleJitter_);
  addRow(jitter, tr("Shift (px)"), shift_);
  addRow(jitter, tr("Light direction"), light_);
  addRow(jitter, tr("Ambient"), ambient_);
  addRow(jitter, tr("Diffuse"), diffuse_);

  QFormLayout* run = addGroup(secondColumn, tr("Run"));
  seed_ = textField("seed", tr("Random seed of the perturbations and shape samples: the same "
                               "seed and data give the same model."));
  seed_->setValidator(new QRegularExpressionValidator(QRegularExpression("[0-9]{1,19}"), seed_));
  threads_ = intField("threads", 0, 64,
                      tr("Worker threads for loading and rendering (0 = one per core but one, "
                         "which keeps the window responsive). The model does not depend on it."));
  addRow(run, tr("Seed"), seed_);
  addRow(run, tr("Threads"), threads_);
  secondColumn->addStretch(1);

  connect(singleView_, &QCheckBox::toggled, this, [this](bool single) {
    yaws_->setEnabled(!single);
    pitches_->setEnabled(!single);
    mirrorRightViews_->setEnabled(!single);
  });
  setSettings(TrainSettings{});
}

TrainSettings SettingsForm::settings() const {
  TrainSettings s;
  s.singleView = singleView_->isChecked();
  if (!s.singleView) {
    s.yawsDeg = parseAngleList(yaws_->text(), "view yaws");
    s.pitchesDeg = parseAngleList(pitches_->text(), "view pitches");
  }
  s.mirrorRightViews = mirrorRightViews_->isChecked();
  s.scales = scales_->value();
  s.patchSize = patchSize_->value();
  s.patchRatio = patchRatio_->value();
  s.samplesPerView = samplesPerView_->value();
  s.hiddenShare = hiddenShare_->value();
  s.supersample = supersample_->value();
  s.textureVariance = textureVariance_->value();
  s.textureMaxModes = textureMaxModes_->value();
  s.shape.varianceKept = shapeVariance_->value();
  s.shape.maxModes = shapeMaxModes_->value();
  s.shape.limitSd = shapeLimit_->value();
  s.shape.mirror = mirrorShapes_->isChecked();
  s.perturbation.rotationDeg = rotation_->value();
  s.perturbation.viewCoverage = viewCoverage_->value();
  s.perturbation.scale = scaleJitter_->value();
  s.perturbation.shiftPixels = shift_->value();
  s.perturbation.lightDirection = light_->value();
  s.perturbation.ambient = ambient_->value();
  s.perturbation.diffuse = diffuse_->value();
  bool ok = false;
  s.seed = seed_->text().toULongLong(&ok);
  if (!ok) throw InputError("training settings: seed: enter a whole number >= 0");
  // 0: every core but one, so that the GUI thread is never starved by the renders.
  s.threads = threads_->value() > 0
                  ? threads_->value()
                  : std::max(1, static_cast<int>(std::thread::hardware_concurrency()) - 1);
  s.validate();
  return s;
}

void SettingsForm::setSettings(const TrainSettings& s) {
  yaws_->setText(formatAngleList(s.yawsDeg));
  pitches_->setText(formatAngleList(s.pitchesDeg));
  singleView_->setChecked(s.singleView);
  mirrorRightViews_->setChecked(s.mirrorRightViews);
  scales_->setValue(s.scales);
  patchSize_->setValue(s.patchSize);
  patchRatio_->setValue(s.patchRatio);
  samplesPerView_->setValue(s.samplesPerView);
  hiddenShare_->setValue(s.hiddenShare);
  supersample_->setValue(s.supersample);
  textureVariance_->setValue(s.textureVariance);
  textureMaxModes_->setValue(s.textureMaxModes);
  shapeVariance_->setValue(s.shape.varianceKept);
  shapeMaxModes_->setValue(s.shape.maxModes);
  shapeLimit_->setValue(s.shape.limitSd);
  mirrorShapes_->setChecked(s.shape.mirror);
  rotation_->setValue(s.perturbation.rotationDeg);
  viewCoverage_->setValue(s.perturbation.viewCoverage);
  scaleJitter_->setValue(s.perturbation.scale);
  shift_->setValue(s.perturbation.shiftPixels);
  light_->setValue(s.perturbation.lightDirection);
  ambient_->setValue(s.perturbation.ambient);
  diffuse_->setValue(s.perturbation.diffuse);
  seed_->setText(QString::number(s.seed));
  threads_->setValue(s.threads);
}

}  // namespace clm3d::ui
