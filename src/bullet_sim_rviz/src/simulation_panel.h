// The Simulation panel: what Gazebo's window offered to run a simulation, inside RViz.
#pragma once

#ifndef Q_MOC_RUN
#include "layout_report.h"
#include "sim_client.h"

#include <rviz/panel.h>
#endif

#include <memory>

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTimer;

namespace bullet_sim_rviz {

/// Sim time, measured real-time factor, pause / play, step N, reset world, reset
/// simulation, the real-time factor setting and the robot that the Place robot tool
/// moves. Everything goes through SimClient (the simulator's services and /clock);
/// this class only lays out widgets and shows what SimClient knows.
class SimulationPanel : public rviz::Panel {
  Q_OBJECT
 public:
  explicit SimulationPanel(QWidget* parent = nullptr);

  void load(const rviz::Config& config) override;
  void save(rviz::Config config) const override;

 private Q_SLOTS:
  void refresh();
  void onStep();
  void onSetFactor();
  void onModelChosen(const QString& model);

 private:
  QPushButton* button(const QString& text, const QString& tip);
  void buildLayout();
  void updateModels(const std::vector<std::string>& models);
  /// The result handler of a request: shows its line in the panel (on the GUI thread).
  SimClient::Done report();
  void showResult(bool ok, const QString& text);
  void writeLayoutReport();

  std::shared_ptr<SimClient> client_;
  QLabel* headline_;
  QLabel* sim_time_;
  QLabel* measured_rtf_;
  QPushButton* pause_;
  QPushButton* play_;
  QPushButton* step_;
  QSpinBox* step_count_;
  QPushButton* reset_world_;
  QPushButton* reset_simulation_;
  QDoubleSpinBox* target_rtf_;
  QPushButton* set_rtf_;
  QComboBox* model_;
  bool user_chose_model_ = false;  ///< typed or picked by the user (or the saved config)
  QLabel* result_;
  QTimer* timer_;
  bool target_rtf_shown_ = false;
  std::unique_ptr<LayoutReport> layout_report_;
};

}  // namespace bullet_sim_rviz
