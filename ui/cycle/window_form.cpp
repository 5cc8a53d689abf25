#include "cycle/window_form.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QToolButton>
#include <algorithm>

#include "linkage/timing_text.h"

namespace linkage::ui {

namespace {

QString q(const std::string& s) {
  return QString::fromStdString(s);
}

// A point that cannot move: on the ground, or pinned to a ground point (a crank's centre).
bool fixedPoint(const Mechanism& m, const Point& p) {
  auto onGround = [&](PointId id) {
    const Point* x = m.point(id);
    const Body* b = x ? m.body(x->body) : nullptr;
    return b && b->ground;
  };
  if (onGround(p.id)) return true;
  return std::any_of(m.joints.begin(), m.joints.end(), [&](const Joint& j) {
    return j.type == JointType::Pin &&
           ((j.a == p.id && j.b && onGround(j.b)) || (j.b == p.id && onGround(j.a)));
  });
}

}  // namespace

WindowForm::WindowForm(QWidget* parent) : QWidget(parent) {
  build();
  showMode();
}

void WindowForm::build() {
  auto* h = new QHBoxLayout(this);
  h->setContentsMargins(0, 0, 0, 0);
  mode_ = new QLabel;
  name_ = new QLineEdit;
  name_->setPlaceholderText(tr("name"));
  name_->setMaximumWidth(110);
  // The characters that separate a window's parts cannot be typed (linkage/timing_text.h).
  name_->setValidator(
      new QRegularExpressionValidator(QRegularExpression(R"([^,+:<>="\s]+)"), name_));
  name_->setToolTip(tr("The window's name (conflicts and the timing table name it)"));
  point_ = new QComboBox;
  point_->setPlaceholderText(tr("choose a point"));
  point_->setSizeAdjustPolicy(QComboBox::AdjustToContents);
  point_->setToolTip(
      tr("The point whose position the window is about (as the canvas names it), or a body's "
         "angle"));
  pick_ = new QToolButton;
  pick_->setText(tr("Pick"));
  pick_->setCheckable(true);
  pick_->setToolTip(tr("Pick the point on the canvas: click it there (Esc cancels)"));
  axis_ = new QComboBox;
  axis_->addItem(tr("y"), QPointF(0, 1));
  axis_->addItem(tr("x"), QPointF(1, 0));
  axis_->setToolTip(tr("Which coordinate of the point: y (up) or x (right)"));
  compare_ = new QComboBox;
  compare_->addItem(tr("below"), true);
  compare_->addItem(tr("above"), false);
  compare_->setToolTip(tr("The window holds where the output is below, or above, the threshold"));
  level_ = new QDoubleSpinBox;
  level_->setRange(-1e6, 1e6);
  level_->setDecimals(3);
  level_->setKeyboardTracking(false);
  level_->setMinimumWidth(110);
  level_->setSuffix(QStringLiteral(" mm"));
  level_->setToolTip(tr("The threshold: type it, or drag its line on the diagram"));
  result_ = new QLabel;
  result_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  add_ = new QPushButton(tr("Add Window"));
  add_->setToolTip(tr("Add this window to the machine's timing"));
  new_ = new QPushButton(tr("New Window"));
  new_->setToolTip(tr("Start a new window (the one shown stays as it is)"));
  for (QWidget* w : std::initializer_list<QWidget*>{mode_, name_, new QLabel(tr("of")), point_,
                                                    pick_, axis_, compare_, level_})
    h->addWidget(w);
  h->addWidget(result_, 1);
  h->addWidget(add_);
  h->addWidget(new_);
  connectFields();
}

void WindowForm::connectFields() {
  connect(name_, &QLineEdit::editingFinished, this, [this] {
    if (quiet_ || !name_->isModified()) return;
    name_->setModified(false);
    autoName_.clear();
    Q_EMIT edited(false);
  });
  connect(name_, &QLineEdit::returnPressed, this, [this] {
    if (target_ < 0) Q_EMIT addRequested();
  });
  connect(point_, &QComboBox::activated, this, [this] {
    outputChosen();
    Q_EMIT edited(true);
  });
  connect(axis_, &QComboBox::activated, this, [this] { Q_EMIT edited(true); });
  connect(compare_, &QComboBox::activated, this, [this] { Q_EMIT edited(false); });
  connect(level_, &QDoubleSpinBox::valueChanged, this, [this] {
    if (!quiet_) Q_EMIT edited(false);
  });
  connect(pick_, &QToolButton::toggled, this, [this](bool on) {
    if (!quiet_) Q_EMIT pickRequested(on);
  });
  connect(add_, &QPushButton::clicked, this, &WindowForm::addRequested);
  connect(new_, &QPushButton::clicked, this, &WindowForm::newRequested);
}

void WindowForm::offer(const Mechanism& m) {
  quiet_ = true;
  const QVariant shown = point_->currentData();
  point_->clear();
  for (const Point& p : m.points)
    if (!fixedPoint(m, p)) {
      const QString l = q(m.pointLabel(p.id));
      point_->addItem(l, QStringList{l, "point"});
    }
  for (const Body& b : m.bodies)
    if (!b.ground) point_->addItem(tr("%1 (angle)").arg(q(b.name)), QStringList{q(b.name), "body"});
  point_->setCurrentIndex(shown.isValid() ? point_->findData(shown) : -1);
  taken_.clear();
  for (const TimingWindow& w : m.timing.windows) taken_.push_back(w.name);
  quiet_ = false;
}

void WindowForm::load(int index, const TimingWindow& w, const Mechanism& m) {
  quiet_ = true;
  target_ = index;
  name_->setText(q(w.name));
  name_->setModified(false);
  autoName_.clear();
  QStringList data;
  if (w.output.body) {
    if (const Body* b = m.body(w.output.body)) data = QStringList{q(b->name), "body"};
  } else if (m.point(w.output.point)) {
    data = QStringList{q(m.pointLabel(w.output.point)), "point"};
  }
  int i = data.isEmpty() ? -1 : point_->findData(data);
  if (i < 0 && !data.isEmpty()) {  // a point that does not move, typed in the line
    point_->addItem(data[0], data);
    i = point_->count() - 1;
  }
  point_->setCurrentIndex(i);
  // A direction other than y or x (typed as DX,DY) is offered as it is, to be kept.
  if (axis_->count() > 2) axis_->removeItem(2);
  const Vec2 d = w.output.direction;
  const QPointF v(d.x(), d.y());
  if (v != QPointF(0, 1) && v != QPointF(1, 0) && !w.output.body)
    axis_->addItem(tr("along %1,%2").arg(q(shortestText(d.x())), q(shortestText(d.y()))), v);
  axis_->setCurrentIndex(std::max(0, axis_->findData(v)));
  compare_->setCurrentIndex(w.below ? 0 : 1);
  outputChosen();
  level_->setValue(w.level);
  showMode();
  quiet_ = false;
}

void WindowForm::startNew() {
  target_ = -1;
  autoName_.clear();
  name_->clear();
  if (point_->currentIndex() >= 0)
    suggestName(point_->currentData().toStringList().value(0).section('.', 0, 0));
  showMode();
}

bool WindowForm::angleChosen() const {
  return point_->currentData().toStringList().value(1) == "body";
}

void WindowForm::outputChosen() {
  axis_->setEnabled(!angleChosen());
  level_->setSuffix(angleChosen() ? QStringLiteral("°") : QStringLiteral(" mm"));
  if (quiet_ || point_->currentIndex() < 0) return;
  // A name the user gave stays; the form's own follows the point chosen.
  if (name_->text().isEmpty() || name_->text() == autoName_)
    suggestName(point_->currentData().toStringList().value(0).section('.', 0, 0));
}

void WindowForm::suggestName(const QString& base) {
  auto taken = [&](const QString& n) {
    return std::find(taken_.begin(), taken_.end(), n.toStdString()) != taken_.end();
  };
  QString name = base;
  for (int k = 2; taken(name) || !validWindowName(name.toStdString()); ++k)
    name = base + QString::number(k);
  name_->setText(name);
  autoName_ = name;
}

std::optional<TimingWindow> WindowForm::window(const Mechanism& m, QString* why) const {
  auto fail = [&](const QString& text) {
    if (why) *why = text;
    return std::nullopt;
  };
  const QStringList d = point_->currentData().toStringList();
  if (d.size() != 2)
    return fail(tr("Choose the window's point in the list, or pick it on the canvas"));
  TimingWindow w;
  w.name = name_->text().trimmed().toStdString();
  if (w.name.empty()) return fail(tr("Give the window a name"));
  if (d[1] == "body") {
    const Body* b = m.bodyNamed(d[0].toStdString());
    if (!b) return fail(tr("No body \"%1\"").arg(d[0]));
    w.output = LimitMeasure::angleOf(b->id);
  } else {
    const std::optional<PointId> p = m.findPoint(d[0].toStdString());
    if (!p) return fail(tr("No point \"%1\"").arg(d[0]));
    const QPointF v = axis_->currentData().toPointF();
    w.output = LimitMeasure::along(*p, Vec2(v.x(), v.y()));
  }
  w.below = compare_->currentData().toBool();
  w.level = level_->value();
  return w;
}

void WindowForm::setLevel(double v) {
  quiet_ = true;
  level_->setValue(v);
  quiet_ = false;
}

double WindowForm::level() const {
  return level_->value();
}

void WindowForm::choosePoint(const Mechanism& m, PointId p) {
  if (!m.point(p)) return;
  const QString l = q(m.pointLabel(p));
  const QStringList data{l, "point"};
  int i = point_->findData(data);
  if (i < 0) {
    point_->addItem(l, data);
    i = point_->count() - 1;
  }
  point_->setCurrentIndex(i);
  outputChosen();
  Q_EMIT edited(true);
}

void WindowForm::setResult(const QString& text) {
  result_->setText(text);
  result_->setToolTip(text);
}

QString WindowForm::resultText() const {
  return result_->text();
}

void WindowForm::setPicking(bool on) {
  quiet_ = true;
  pick_->setChecked(on);
  quiet_ = false;
}

void WindowForm::showMode() {
  mode_->setText(target_ < 0 ? tr("New window") : tr("Edit window"));
  add_->setVisible(target_ < 0);
  new_->setVisible(target_ >= 0);
}

QStringList WindowForm::probeLines() const {
  QStringList out;
  out << QStringLiteral("cycle window: %1; name %2; point %3; axis %4; %5; level %6; result %7")
             .arg(target_ < 0 ? QStringLiteral("new") : QStringLiteral("edit %1").arg(target_))
             .arg(name_->text(), point_->currentText(), axis_->currentText(),
                  compare_->currentText())
             .arg(level_->value(), 0, 'g', 12)
             .arg(result_->text());
  out << QStringLiteral("cycle picking: %1").arg(pick_->isChecked() ? 1 : 0);
  const std::pair<const char*, const QWidget*> parts[] = {
      {"name", name_},       {"point", point_}, {"pick", pick_}, {"axis", axis_},
      {"compare", compare_}, {"level", level_}, {"add", add_},   {"new", new_}};
  for (const auto& [name, w] : parts)
    if (w->isVisible()) {
      const QPoint c = w->mapToGlobal(w->rect().center());
      out << QStringLiteral("at cycle window %1: %2 %3")
                 .arg(QLatin1String(name))
                 .arg(c.x())
                 .arg(c.y());
    }
  return out;
}

}  // namespace linkage::ui
