// Edits of a cam as the editor's cam table makes them (ui/cam/), on a copy of the design: the
// cam made for a follower as drawn, its motion programme, its base circle and roller. The
// drawing is the follower's lowest position (../shared/specs/model-format.md, "Cams"), so a
// base that changes moves the follower there: along its slot (translating) or about its pivot
// (oscillating), rigidly; the bodies joined to it follow when the design is solved.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "linkage/cam.h"
#include "linkage/model.h"

namespace linkage {

// The bodies a cam for the follower at point b could be on: those pinned to the body b's body
// is guided by (its one slider in a straight slot, or its one pin), b's body not among them.
// Empty with why when b's body is no follower (no such joint, or more than one).
std::vector<BodyId> camBodiesFor(const Mechanism& m, PointId b, std::string* why = nullptr);

// A cam on `cam` (pinned at a to the follower's guide) moving the follower at b, sized for b as
// drawn (base + roller reaches b: the pitch circle through it; the roller a quarter of that,
// none for `flat`), with a first programme (a cycloidal rise over 120 degrees, a dwell to
// 180, a cycloidal return to 300, a dwell: a quarter of the base in mm, or 10 degrees).
// Refused with why when b's body has a cam already or the cam cannot be made there.
JointId addCam(Mechanism& m, PointId b, BodyId cam, bool flat, std::string* why = nullptr);

// The segments as the file writes them (to_deg, rise_mm or rise_deg, law).
std::vector<Record> camMotionRecords(std::span<const cam::Segment> segments, bool oscillating);
// The programme of cam joint j; refused with why naming motion[k] for one that is not one.
bool setCamMotion(Mechanism& m, JointId j, std::span<const cam::Segment> segments,
                  std::string* why = nullptr);
// A rise typed as the Cam dock types it: segment k's rise set to `rise`, the programme kept
// closed by the next segment with a law moving the other way (round the turn; the way of the new
// rise, or of the old one when the new is 0) taking the difference. False, s unchanged, when
// none does. The sensitivities' `cam:...segmentK.rise` is this change (risePartner: its other
// segment, for a rise moving `way`; -1 when none).
bool withCamRise(std::vector<cam::Segment>& s, size_t k, double rise);
int risePartner(std::span<const cam::Segment> s, size_t k, double way);
// The base circle's radius, the follower moved to its new lowest position; refused with why
// where it cannot be (a slot that misses the circle, an arm that cannot reach it).
bool setCamBase(Mechanism& m, JointId j, double baseMm, std::string* why = nullptr);
// Cam joint j's parts put back where the drawing's rules want them after other edits moved
// what they rest on (the sensitivities' dimensions: linkage/dimension_change.h): the cam's body
// translated so that its centre a is on the guide's pin there, the follower translated onto its
// pivot (oscillating) or b onto its slot's line (translating), then to its lowest position
// (setCamBase with the base as it is). Nothing moves where nothing is off. Refused with why
// where it cannot be.
bool replaceCam(Mechanism& m, JointId j, std::string* why = nullptr);
// The roller's radius (0 a knife edge) with the pitch curve kept (base + roller fixed, the
// follower not moved); refused for a flat face and for a roller of base + roller or more.
bool setCamRoller(Mechanism& m, JointId j, double rollerMm, std::string* why = nullptr);

}  // namespace linkage
