// The entries of a machine's Cycle dock, as the user types them: rows ("needlebar.N:y"),
// windows ("needle=needlebar.N:y<-150"), conflicts ("needle,feed": the two must not overlap)
// and clearances ("hook.K needlebar.N" or "hook.K needlebar.N min 0.1"; a side may be a slot,
// "ground.plate"). Each kind is read into the document's Timing (linkage/model.h) and written
// back from it (linkage/timing_text.h): a typed entry is kept by ids, so a rename follows it.
#pragma once

#include <QString>

#include "linkage/model.h"

namespace linkage::ui {

enum class EntryKind { Row, Window, Conflict, Clearance };
constexpr EntryKind kEntryKinds[] = {EntryKind::Row, EntryKind::Window, EntryKind::Conflict,
                                     EntryKind::Clearance};

// "Row", "Window", ... and what to type for one ("body.point:y  (or :x, :DX,DY, body:angle)").
QString kindName(EntryKind k);
QString kindHint(EntryKind k);

int entryCount(const Timing& t, EntryKind k);
QString entryText(const Mechanism& m, EntryKind k, int index);

// Reads `text` as an entry of kind k into m's timing: at `index`, or added at the end when
// index is -1. False, with why (the part that is wrong), leaving m as it was.
bool setEntry(Mechanism& m, EntryKind k, int index, const QString& text, QString* why);
// Takes entry `index` out (a window with the conflicts that name it).
void removeEntry(Mechanism& m, EntryKind k, int index);

// "the clearance hook.K – needlebar.N", "the window needle", ... for the undo history.
QString entryTitle(const Mechanism& m, EntryKind k, int index);

}  // namespace linkage::ui
