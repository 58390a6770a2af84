#include "simulation_panel.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPointer>
#include <QPushButton>
#include <QSpinBox>
#include <QTimer>
#include <QVBoxLayout>

#include <pluginlib/class_list_macros.hpp>
#include <ros/node_handle.h>

namespace bullet_sim_rviz {
namespace {

// The labels follow /clock this often; cheap, and smooth enough to read.
constexpr int kRefreshMs = 100;

}  // namespace

SimulationPanel::SimulationPanel(QWidget* parent)
    : rviz::Panel(parent), client_(SimClient::shared()) {
  buildLayout();
  std::string report_path;
  ros::NodeHandle("~").param<std::string>("sim_panel_layout_report", report_path, "");
  layout_report_ = std::make_unique<LayoutReport>(QString::fromStdString(report_path));

  connect(pause_, &QPushButton::clicked, this, [this] { client_->pause(report()); });
  connect(play_, &QPushButton::clicked, this, [this] { client_->play(report()); });
  connect(step_, &QPushButton::clicked, this, &SimulationPanel::onStep);
  connect(reset_world_, &QPushButton::clicked, this, [this] { client_->resetWorld(report()); });
  connect(reset_simulation_, &QPushButton::clicked, this,
          [this] { client_->resetSimulation(report()); });
  connect(set_rtf_, &QPushButton::clicked, this, &SimulationPanel::onSetFactor);
  connect(model_, &QComboBox::currentTextChanged, this, &SimulationPanel::onModelChosen);
  timer_ = new QTimer(this);
  connect(timer_, &QTimer::timeout, this, &SimulationPanel::refresh);
  timer_->start(kRefreshMs);
}

QPushButton* SimulationPanel::button(const QString& text, const QString& tip) {
  auto* b = new QPushButton(text);
  b->setToolTip(tip);
  return b;
}

void SimulationPanel::buildLayout() {
  headline_ = new QLabel;
  headline_->setWordWrap(true);
  QFont bold = headline_->font();
  bold.setBold(true);
  headline_->setFont(bold);
  sim_time_ = new QLabel("-");
  measured_rtf_ = new QLabel("-");
  pause_ = button("Pause", "/gazebo/pause_physics");
  play_ = button("Play", "/gazebo/unpause_physics");
  step_ = button("Step", "Pause, then advance this many physics steps (/gazebo/step_simulation)");
  step_count_ = new QSpinBox;
  step_count_->setRange(1, 1000000);
  step_count_->setSuffix(" steps");
  reset_world_ = button("Reset world", "Models back to their start poses (/gazebo/reset_world)");
  reset_simulation_ = button("Reset simulation", "Time to 0 and models back (/gazebo/reset_simulation)");
  target_rtf_ = new QDoubleSpinBox;
  target_rtf_->setRange(0, 1000);
  target_rtf_->setDecimals(2);
  target_rtf_->setValue(1);
  target_rtf_->setSpecialValueText("as fast as possible");
  target_rtf_->setToolTip("0 = as fast as possible (max_update_rate 0)");
  set_rtf_ = button("Set", "/gazebo/set_physics_properties: max_update_rate = factor / time_step");
  model_ = new QComboBox;
  model_->setEditable(true);
  model_->setToolTip("The model the Place robot tool moves (/gazebo/get_world_properties)");
  result_ = new QLabel;
  result_->setWordWrap(true);

  auto* grid = new QGridLayout;
  grid->addWidget(new QLabel("Sim time"), 0, 0);
  grid->addWidget(sim_time_, 0, 1, 1, 2);
  grid->addWidget(new QLabel("Real-time factor"), 1, 0);
  grid->addWidget(measured_rtf_, 1, 1, 1, 2);
  grid->addWidget(pause_, 2, 0);
  grid->addWidget(play_, 2, 1, 1, 2);
  grid->addWidget(step_, 3, 0);
  grid->addWidget(step_count_, 3, 1, 1, 2);
  grid->addWidget(reset_world_, 4, 0);
  grid->addWidget(reset_simulation_, 4, 1, 1, 2);
  grid->addWidget(new QLabel("Target factor"), 5, 0);
  grid->addWidget(target_rtf_, 5, 1);
  grid->addWidget(set_rtf_, 5, 2);
  grid->addWidget(new QLabel("Robot"), 6, 0);
  grid->addWidget(model_, 6, 1, 1, 2);
  auto* column = new QVBoxLayout(this);
  column->addWidget(headline_);
  column->addLayout(grid);
  column->addWidget(result_);
  column->addStretch(1);
}

SimClient::Done SimulationPanel::report() {
  QPointer<SimulationPanel> self(this);
  return [self](bool ok, const std::string& text) {
    const QString line = QString::fromStdString(text);
    // Called on SimClient's worker thread: widgets are touched on the GUI thread only.
    QMetaObject::invokeMethod(
        qApp, [self, ok, line] { if (self) self->showResult(ok, line); }, Qt::QueuedConnection);
  };
}

void SimulationPanel::showResult(bool ok, const QString& text) {
  result_->setStyleSheet(ok ? "" : "color: #c00000;");
  result_->setText(text);
}

void SimulationPanel::onStep() {
  client_->step(static_cast<uint32_t>(step_count_->value()), report());
}

void SimulationPanel::onSetFactor() { client_->setRealTimeFactor(target_rtf_->value(), report()); }

void SimulationPanel::onModelChosen(const QString& model) {
  user_chose_model_ = true;  // signals are blocked while the panel itself sets the choice
  client_->selectModel(model.toStdString());
  Q_EMIT configChanged();
}

void SimulationPanel::updateModels(const std::vector<std::string>& models) {
  QStringList names;
  for (const std::string& m : models) names << QString::fromStdString(m);
  QStringList shown;
  for (int i = 0; i < model_->count(); ++i) shown << model_->itemText(i);
  if (names == shown) return;
  const QString chosen = model_->currentText();
  const QSignalBlocker block(model_);
  model_->clear();
  model_->addItems(names);
  // Keep the user's choice; without one, the last model: the simulator lists the world's
  // models first and spawned robots after them, newest last (a robot spawned later takes
  // over an automatic choice).
  const bool keep = user_chose_model_ && !chosen.isEmpty();
  model_->setCurrentText(keep || names.isEmpty() ? chosen : names.back());
  client_->selectModel(model_->currentText().toStdString());
}

void SimulationPanel::refresh() {
  const SimSnapshot s = client_->snapshot();
  headline_->setText(QString::fromStdString(headline(s)));
  headline_->setStyleSheet(s.services_available ? "" : "color: #c00000;");
  sim_time_->setText(QString::fromStdString(simTimeText(s.sim_time_s)));
  measured_rtf_->setText(QString::fromStdString(rtfText(s.measured_rtf)));
  for (QWidget* w : std::initializer_list<QWidget*>{pause_, play_, step_, reset_world_,
                                                    reset_simulation_, set_rtf_})
    w->setEnabled(s.services_available);
  pause_->setEnabled(s.services_available && !isPaused(s));
  play_->setEnabled(s.services_available && isPaused(s));
  // The simulator's setting fills the box once; after that it is the user's.
  if (s.target_rtf && !target_rtf_shown_) {
    target_rtf_->setValue(*s.target_rtf);
    target_rtf_shown_ = true;
  }
  updateModels(s.models);
  writeLayoutReport();
}

void SimulationPanel::writeLayoutReport() {
  QStringList models;
  for (int i = 0; i < model_->count(); ++i) models << model_->itemText(i);
  layout_report_->write(
      {{"pause", pause_}, {"play", play_}, {"step", step_}, {"step_count", step_count_},
       {"reset_world", reset_world_}, {"reset_simulation", reset_simulation_},
       {"target_rtf", target_rtf_}, {"set_rtf", set_rtf_}, {"model", model_}},
      {{"headline", headline_->text()}, {"sim_time", sim_time_->text()},
       {"measured_rtf", measured_rtf_->text()}, {"result", result_->text()},
       {"model", model_->currentText()}, {"models", models.join(",")}});
}

void SimulationPanel::load(const rviz::Config& config) {
  rviz::Panel::load(config);
  int steps = 1;
  if (config.mapGetInt("Step Count", &steps)) step_count_->setValue(steps);
  QString model;
  if (config.mapGetString("Robot", &model) && !model.isEmpty()) {
    model_->setCurrentText(model);
    user_chose_model_ = true;
  }
}

void SimulationPanel::save(rviz::Config config) const {
  rviz::Panel::save(config);
  config.mapSetValue("Step Count", step_count_->value());
  config.mapSetValue("Robot", model_->currentText());
}

}  // namespace bullet_sim_rviz

PLUGINLIB_EXPORT_CLASS(bullet_sim_rviz::SimulationPanel, rviz::Panel)
