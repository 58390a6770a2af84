// For GUI tests: where the panel's widgets are on the screen, written to a JSON file.
#pragma once

#include <QString>
#include <QWidget>

#include <map>
#include <string>

namespace bullet_sim_rviz {

/// Writes {"widgets": {name: {x, y, w, h}}, "texts": {name: text}} (screen pixels) to `path`
/// when it differs from what was written last. Tests click the buttons there with xdotool,
/// as the workspace's other GUI tests do; an empty path writes nothing.
class LayoutReport {
 public:
  explicit LayoutReport(QString path) : path_(std::move(path)) {}
  void write(const std::map<std::string, const QWidget*>& widgets,
             const std::map<std::string, QString>& texts);

 private:
  QString path_;
  QByteArray last_;
};

}  // namespace bullet_sim_rviz
