// The Properties panel as a form builder (properties/forms.h): the form of what is selected,
// then the sections other folders add to it (forms/form.h), the joint's rows said by its element
// kind (elements/element_ui.h). The panel itself knows no forces: a panel on its own has no
// mass rows; the window's has them, added by the forces' feature.
#include <gtest/gtest.h>

#include "ui_test.h"

#include <QFormLayout>
#include <QLabel>
#include <QRegularExpression>
#include <QSignalSpy>
#include <set>

#include "document/commands.h"
#include "document/document.h"
#include "drawing.h"
#include "elements/element_ui.h"
#include "linkage/edits.h"
#include "linkage/io/model_lookup.h"
#include "properties/properties_panel.h"
#include "tools/selection.h"

namespace linkage::ui {
namespace {

class FormsTest : public ::testing::Test {
 protected:
  void open(const std::string& name) {
    ASSERT_TRUE(doc.open(QString::fromStdString(*resolveModel(name)), nullptr)) << name;
    selection.clear();
  }
  // The rows' labels, top to bottom.
  QStringList labels() const {
    QStringList out;
    auto* form = panel.findChild<QFormLayout*>();
    for (int i = 0; i < form->rowCount(); ++i) {
      QLayoutItem* l = form->itemAt(i, QFormLayout::LabelRole);
      auto* label = l ? qobject_cast<QLabel*>(l->widget()) : nullptr;
      out << (label ? label->text() : QString());
    }
    return out;
  }
  Document doc;
  Selection selection;
  PropertiesPanel panel;
};

// Rows for a test: after a point's own, one row that reads the mechanism's name; its shape is
// the name, so that renaming the mechanism makes the rows anew.
FormSection nameSection() {
  return FormSection{
      "point", [](const Mechanism& m, const FormTarget&) { return QString::fromStdString(m.name); },
      [](Form& form, const FormTarget&) {
        Document* doc = form.document();
        form.addInfo(QStringLiteral("Extra"),
                     [doc] { return QString::fromStdString(doc->design().name); });
      }};
}

TEST_F(FormsTest, ASectionFollowsItsFormsOwnRowsAndNoOtherForm) {
  open("four-bar-crank-rocker");
  panel.setDocument(&doc, &selection);
  panel.addSection(nameSection());
  const Mechanism& m = doc.design();
  selection.add(m.points[0].id);
  const QStringList rows = labels();
  ASSERT_FALSE(rows.isEmpty());
  EXPECT_EQ(rows.front(), "Name");
  EXPECT_EQ(rows.back(), "Extra") << rows.join(", ").toStdString();
  EXPECT_EQ(rows.count("Extra"), 1);
  selection.clear();
  selection.add(m.bodyNamed("coupler")->id);
  EXPECT_FALSE(labels().contains("Extra"));
  EXPECT_EQ(panel.field("Extra"), nullptr);
  selection.clear();
  EXPECT_TRUE(panel.title().contains("Mechanism"));
  EXPECT_FALSE(labels().contains("Extra"));
}

TEST_F(FormsTest, ASectionsShapeMakesTheRowsAnewAndOnlyIt) {
  open("four-bar-crank-rocker");
  panel.setDocument(&doc, &selection);
  panel.addSection(nameSection());
  selection.add(doc.design().points[0].id);
  QSignalSpy rebuilt(&panel, &PropertiesPanel::rebuilt);
  // An edit that changes nothing of the shape: the rows are refreshed, not made anew.
  Mechanism moved = doc.design();
  moved.points[0].name = "renamed";
  commitEdit(&doc, "Rename point", std::move(moved));
  EXPECT_EQ(rebuilt.count(), 0);
  Mechanism renamed = doc.design();
  renamed.name = "another name";
  commitEdit(&doc, "Rename the mechanism", std::move(renamed));
  EXPECT_EQ(rebuilt.count(), 1);
  auto* extra = qobject_cast<QLabel*>(panel.field("Extra"));
  ASSERT_NE(extra, nullptr);
  EXPECT_EQ(extra->text(), "another name");
}

// A link's form says what its dimensions do to the output at the crank angle: the Wanzer
// triangle's side EG (its points pinned to one-point blocks only, so that typing it moves
// nothing else's dimension) moves the needle as a side typed 1e-4 mm longer and solved does,
// to second order.
TEST_F(FormsTest, ALinksFormSaysWhatItsSidesDoToTheOutput) {
  open("wanzer-inversion-2");
  doc.setCrankDeg(70);
  panel.setDocument(&doc, &selection);
  const BodyId triangle = doc.design().bodyNamed("triangle")->id;
  selection.add(triangle);
  auto* effect = qobject_cast<QLabel*>(panel.field("Effect"));
  ASSERT_NE(effect, nullptr);
  const QString text = effect->text();
  ASSERT_TRUE(text.startsWith("needlebar.G moves, here, by")) << text;
  shot(&panel, "link_effect");
  const QRegularExpression line(QStringLiteral("E-G: x (\\S+), y (\\S+) mm per mm"));
  const QRegularExpressionMatch got = line.match(text);
  ASSERT_TRUE(got.hasMatch()) << text;
  const double dy = got.captured(2).toDouble();
  Mechanism next = doc.design();
  std::vector<double> sides = sideLengths(next, triangle);
  sides[2] += 1e-4;  // |P0P2|: E-G
  ASSERT_TRUE(setSideLengths(next, triangle, sides));
  Kinematics k = doc.kinematics();
  const PointId G = *next.findPoint("needlebar.G");
  const double before = k.position(G).y();
  ASSERT_TRUE(k.edit(next).ok());
  EXPECT_NEAR((k.position(G).y() - before) / 1e-4, dy, 2e-3 * std::max(1.0, std::abs(dy)) + 1e-4)
      << text;
  EXPECT_GT(std::abs(dy), 0.01);
}

// The forces' rows are the forces' (ui/forces/), added to the window's panel, not the panel's.
TEST_F(FormsTest, APanelOnItsOwnHasNoMassRowsTheWindowsHas) {
  open("four-bar-crank-rocker");
  panel.setDocument(&doc, &selection);
  selection.add(doc.design().bodyNamed("coupler")->id);
  EXPECT_NE(panel.field("Side AB [mm]"), nullptr);
  EXPECT_EQ(panel.field("Mass [kg]"), nullptr);
  MainWindow w;
  ASSERT_TRUE(test::showExample(w, "four-bar-crank-rocker"));
  w.tools().selection()->add(w.document()->design().bodyNamed("coupler")->id);
  EXPECT_NE(w.properties().panel()->field("Side AB [mm]"), nullptr);
  EXPECT_NE(w.properties().panel()->field("Mass [kg]"), nullptr);
}

// Each kind puts its rows on a joint's form, its type first; the examples hold every kind.
TEST_F(FormsTest, EveryElementKindFillsTheFormOfItsJoints) {
  std::set<JointType> seen;
  for (const std::string& name : listExamples()) {
    open(name);
    panel.setDocument(&doc, &selection);
    for (const Joint& j : doc.design().joints) {
      selection.clear();
      selection.add(j.id);
      EXPECT_TRUE(panel.title().startsWith("<b>Joint</b>")) << name << ": " << panel.title();
      const QStringList rows = labels();
      ASSERT_FALSE(rows.isEmpty()) << name;
      EXPECT_EQ(rows.front(), "Type") << name << ": " << panel.title();
      seen.insert(j.type);
    }
  }
  for (const ElementUi* e : elementUis()) {
    EXPECT_NE(e->form, nullptr) << e->describe;
    EXPECT_TRUE(seen.count(e->type)) << "no example has a " << e->describe;
  }
}

}  // namespace
}  // namespace linkage::ui
