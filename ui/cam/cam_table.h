// A cam's motion programme as a table a designer types in (linkage/cam.h): a row per segment,
// its start (the previous end), its end, its law (or a dwell) and its rise (mm, or degrees for
// an oscillating follower; negative a fall). An edit asks for the whole programme as edited
// (edited()): the panel takes it as one undo step or says why not, and the table shows the
// document's programme again. A rise typed keeps the programme closed: the next segment that
// moves the other way (after it, round the turn) takes the difference.
#pragma once

#include <QWidget>
#include <vector>

#include "linkage/cam.h"

class QTableWidget;
class QPushButton;

namespace linkage::ui {

class CamTable : public QWidget {
  Q_OBJECT

 public:
  explicit CamTable(QWidget* parent = nullptr);

  // Shows a programme (no edited() for it).
  void setSegments(const std::vector<cam::Segment>& s, bool oscillating);
  const std::vector<cam::Segment>& segments() const { return segments_; }
  QTableWidget* table() const { return table_; }

  // The edits the table's cells and buttons make, for the panel and the tests: segment k's end,
  // its rise (the next segment moving the other way taking the difference; false when none
  // does), its law (none: a dwell; the rise kept); segment k split at its middle into two
  // halves of its rise; segment k joined to the one before it (to the next, for the first).
  static std::vector<cam::Segment> withEnd(std::vector<cam::Segment> s, size_t k, double deg);
  static bool withRise(std::vector<cam::Segment>& s, size_t k, double rise);
  static std::vector<cam::Segment> withLaw(std::vector<cam::Segment> s, size_t k,
                                           std::optional<cam::Law> law);
  static std::vector<cam::Segment> split(std::vector<cam::Segment> s, size_t k);
  static std::vector<cam::Segment> joined(std::vector<cam::Segment> s, size_t k);

 Q_SIGNALS:
  // The programme as edited, and the undo step's name.
  void edited(const std::vector<cam::Segment>& s, const QString& what);
  // A cell's text is not a number.
  void refused(const QString& why);

 private:
  void fill();
  void ask(const std::vector<cam::Segment>& s, const QString& what);
  void cellEdited(int row, int column);
  int selectedRow() const;

  QTableWidget* table_;
  QPushButton *split_, *join_;
  std::vector<cam::Segment> segments_;
  bool oscillating_ = false, filling_ = false;
  bool asked_ = false;  // an edit was asked for: the next programme shown is filled in
};

}  // namespace linkage::ui
