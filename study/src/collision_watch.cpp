#include "study/collision_watch.hpp"

namespace study {

namespace {

/// A contact point this high above the board's surface is on a post (m).
constexpr double kAboveBoard = 0.001;

/// 0 for the left arm's bodies, 1 for the right's, -1 for anything else.
int armOf(const std::string& body) {
  if (body.starts_with("/raven2/left/")) return 0;
  if (body.starts_with("/raven2/right/")) return 1;
  return -1;
}

bool isBoard(const std::string& body) {
  return body.ends_with("/peg_board");
}

}  // namespace

std::string collisionEvent(CollisionKind kind) {
  switch (kind) {
    case CollisionKind::Tool:
      return "tool_collision";
    case CollisionKind::Board:
      return "board_collision";
    case CollisionKind::Post:
      return "post_collision";
  }
  return "collision";
}

CollisionWatch::CollisionWatch(std::optional<scenario::BoardGeometry> board) : board_(board) {}

void CollisionWatch::observe(double time, const std::vector<ambf_like::Contact>& contacts,
                             EventLog& events) {
  bool tools = false;
  raven::PerArm<bool> board{}, post{};
  for (const ambf_like::Contact& c : contacts) {
    if (c.soft || (c.distance > 0.0 && c.normal_impulse <= 0.0)) continue;  // a ring, a gap
    const int a = armOf(c.body_a), b = armOf(c.body_b);
    if (a >= 0 && b >= 0) {
      tools = tools || a != b;
      continue;
    }
    const int arm = a >= 0 ? a : b;
    const std::string& other = a >= 0 ? c.body_b : c.body_a;
    if (arm < 0 || !board_ || !isBoard(other)) continue;
    const bool on_post = c.position_on_b.z() > board_->board_top + kAboveBoard;
    (on_post ? post : board)[static_cast<std::size_t>(arm)] = true;
  }
  track(tools_, tools, time, CollisionKind::Tool, -1, events);
  for (std::size_t a = 0; a < 2; ++a) {
    track(boards_[a], board[a], time, CollisionKind::Board, static_cast<int>(a), events);
    track(posts_[a], post[a], time, CollisionKind::Post, static_cast<int>(a), events);
  }
}

void CollisionWatch::track(Episode& episode, bool touching, double time, CollisionKind kind,
                           int arm, EventLog& events) {
  if (touching) {
    if (!episode.open) events.add(time, collisionEvent(kind), arm);
    episode.open = true;
    episode.last_touch = time;
  } else if (episode.open && time - episode.last_touch >= kEpisodeGap) {
    events.add(time, collisionEvent(kind) + "_end", arm);
    episode.open = false;
  }
}

bool CollisionWatch::touchingBoard() const {
  for (std::size_t a = 0; a < 2; ++a) {
    if (boards_[a].open || posts_[a].open) return true;
  }
  return false;
}

}  // namespace study
