#include "layout_report.h"

#include <QFile>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSaveFile>

namespace bullet_sim_rviz {

void LayoutReport::write(const std::map<std::string, const QWidget*>& widgets,
                         const std::map<std::string, QString>& texts) {
  if (path_.isEmpty()) return;
  QJsonObject boxes;
  for (const auto& [name, widget] : widgets) {
    const QPoint corner = widget->mapToGlobal(QPoint(0, 0));
    boxes[QString::fromStdString(name)] = QJsonObject{
        {"x", corner.x()}, {"y", corner.y()}, {"w", widget->width()}, {"h", widget->height()},
        {"visible", widget->isVisible()}, {"enabled", widget->isEnabled()}};
  }
  QJsonObject labels;
  for (const auto& [name, text] : texts) labels[QString::fromStdString(name)] = text;
  const QByteArray json =
      QJsonDocument(QJsonObject{{"widgets", boxes}, {"texts", labels}}).toJson();
  if (json == last_) return;
  // Written whole and renamed into place, so a test never reads half a file.
  QSaveFile file(path_);
  if (file.open(QIODevice::WriteOnly) && file.write(json) == json.size() && file.commit())
    last_ = json;
}

}  // namespace bullet_sim_rviz
