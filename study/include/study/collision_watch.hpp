#pragma once
// The instruments' collisions during a trial, as the surgical simulators count them (one per
// contact episode): the two arms touching each other, and a tool touching the board or a post.
// Fed the world's contacts after every manual-loop iteration, it writes an event when an
// episode begins and when it ends.

#include <optional>
#include <string>
#include <vector>

#include "ambf_like/world.hpp"
#include "raven/arm.hpp"
#include "scenario/ring_view.hpp"
#include "study/trial_events.hpp"

namespace study {

/// What an arm's body touched.
enum class CollisionKind { Tool, Board, Post };

/// The event names of an episode's beginning and end: "tool_collision" (arm -1: the two arms),
/// "board_collision", "post_collision" (the arm that touched), each with "_end".
std::string collisionEvent(CollisionKind kind);

/// Counts contact episodes of the Raven's arms (bodies under /raven2/left/, /raven2/right/).
class CollisionWatch {
 public:
  /// `board`: the peg board's geometry when the scene has one (its body "peg_board"; a contact
  /// higher than 1 mm above its surface is on a post); without it only the arms are watched.
  explicit CollisionWatch(std::optional<scenario::BoardGeometry> board);

  /// Touches closer apart than this belong to one episode: contact points flicker for a step or
  /// two as a tool slides, and no person lifts a tool and brings it back down faster (the
  /// quickest voluntary correction takes about 0.1 s).
  static constexpr double kEpisodeGap = 0.1;

  /// The contacts of the last step at trial time `time` (s).
  void observe(double time, const std::vector<ambf_like::Contact>& contacts, EventLog& events);
  /// Whether an arm touches the board or a post now (the status line says so).
  bool touchingBoard() const;

 private:
  /// One kind of contact for one arm (or the pair): is an episode open, when was it last felt.
  struct Episode {
    bool open = false;
    double last_touch = 0.0;
  };
  void track(Episode& episode, bool touching, double time, CollisionKind kind, int arm,
             EventLog& events);

  std::optional<scenario::BoardGeometry> board_;
  Episode tools_;
  raven::PerArm<Episode> boards_, posts_;
};

}  // namespace study
