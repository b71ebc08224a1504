// The model half of the training page: a choice of the project's models, and for the chosen (or
// just trained) model its summary, the mean-patch grid and the shape-mode explorer. Model files
// are read on a worker thread; a broken file gives an error dialog naming it.
#pragma once

#include <QWidget>
#include <filesystem>
#include <memory>
#include <vector>

#include "core/model/clm_model.hpp"

class QComboBox;
class QLabel;
class QSplitter;

namespace clm3d::ui {

class JobRunner;
class MeanPatchGrid;
class ShapeModeExplorer;

class ModelView : public QWidget {
  Q_OBJECT
 public:
  explicit ModelView(QWidget* parent = nullptr);

  // The models to choose from (absolute paths); keeps the shown model selected if it is listed.
  void setModels(const std::vector<std::filesystem::path>& models);
  // Shows a model already in memory (just trained) and selects its file in the list.
  void showModel(std::shared_ptr<const ClmModel> model, const std::filesystem::path& file);
  // Reads `file` on a worker thread and shows it; an error dialog names the file if it is broken.
  void openModel(const std::filesystem::path& file);
  void clear();

  std::shared_ptr<const ClmModel> model() const { return model_; }
  const std::filesystem::path& modelFile() const { return file_; }
  QComboBox* choice() const { return choice_; }
  MeanPatchGrid* patches() const { return patches_; }
  ShapeModeExplorer* shapes() const { return shapes_; }
  JobRunner* loader() const { return loader_; }

 signals:
  void modelShown(const QString& file);

 private:
  void selectFile(const std::filesystem::path& file);
  void startLoading();

  QComboBox* choice_;
  QLabel* summary_;
  QSplitter* split_;
  MeanPatchGrid* patches_;
  ShapeModeExplorer* shapes_;
  JobRunner* loader_;
  std::shared_ptr<const ClmModel> model_;
  std::filesystem::path file_;
  std::filesystem::path pending_;                       // asked for while another file was loading
  std::shared_ptr<std::shared_ptr<ClmModel>> loading_;  // filled by the worker
  std::filesystem::path loadingFile_;
  bool loadBusy_ = false;  // from start until the loader's ended signal
};

}  // namespace clm3d::ui
