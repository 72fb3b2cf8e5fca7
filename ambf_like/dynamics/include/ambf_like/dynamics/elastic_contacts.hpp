#pragma once
// The Coulomb contacts and pins of an elastic body, solved through its implicit system's inverse.

#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <functional>
#include <utility>
#include <vector>

namespace ambf_like::detail {

/// One node of an elastic body pressed against a rigid surface over a step, or pinned to a
/// point of a rigid body (a grasp assist's anchor).
struct ElasticContact {
  int node = 0;
  Eigen::Vector3d normal{0, 0, 0};            ///< the surface's, pointing to the node
  Eigen::Vector3d surface_velocity{0, 0, 0};  ///< of the surface (or pin) at the node
  double least_normal_velocity = 0;           ///< what normal . v must reach to end the step on it
  double start_depth = 0;  ///< how far inside the surface the node began the step
  double friction = 0;     ///< Coulomb's mu
  /// Of something that does not move (the world's static parts): caught between it and a moving
  /// surface, a node stays on it.
  bool fixed_surface = false;
  /// A pin: the node ends the step moving at exactly surface_velocity, pushed or pulled, in no
  /// cone (normal, least_normal_velocity, start_depth and friction play no part).
  bool pinned = false;
  Eigen::Vector3d impulse{0, 0, 0};  ///< on the node (N s): in, the last step's; out, this one's
};

/// Two contacts, by their indices.
using ContactPair = std::pair<std::size_t, std::size_t>;

/// The velocity the nodes answer unit impulses on one node with (3 columns, 3 rows per node).
using NodeResponse = Eigen::Matrix<double, Eigen::Dynamic, 3>;

/// Finds the impulses that leave every contact node on its surface and inside its friction cone
/// (sliding against mu times its normal impulse, or stuck), and every pinned node on its pin,
/// given the velocities the nodes would have without them and each node's response to an
/// impulse (3x3 blocks of the implicit system's inverse). The contacts that pressed last time
/// are first solved together as stuck (a dense Cholesky of their blocks, kept while the same
/// nodes press), taken only if every impulse presses and stays in its cone; a projected
/// Gauss-Seidel then finishes, warm started from the last impulses; after each of its sweeps a
/// node caught between two surfaces that face each other passes no load from one to the other.
class ElasticContactSolver {
 public:
  using ResponseOf = std::function<const NodeResponse&(int node)>;

  /// `contacts` get their impulses (in: a warm start); `free_velocity` has 3 entries per node.
  void solve(const Eigen::VectorXd& free_velocity, std::vector<ElasticContact>& contacts,
             const ResponseOf& response);
  /// Drops what was kept of the responses (the system changed).
  void forget();

 private:
  /// The contact nodes of the last solve (in order) and their blocks of the inverse:
  /// w[j * slots + i] is node j's velocity per impulse on node i, w_inverse[i] inverts w[i, i].
  struct Blocks {
    std::vector<int> nodes;
    std::vector<Eigen::Matrix3d> w;
    std::vector<Eigen::Matrix3d> w_inverse;
  };
  /// The contact nodes last solved as stuck together (in order), and their system factored.
  struct Stuck {
    std::vector<int> nodes;
    Eigen::LLT<Eigen::MatrixXd> factor;
  };

  /// Takes out what only passes through a node between the `pinches`' two contacts (which face
  /// each other); `velocity` (per slot) follows what that changes of the node's own impulse.
  void releasePinches(std::vector<ElasticContact>& contacts,
                      const std::vector<std::size_t>& slot_of,
                      const std::vector<ContactPair>& pinches,
                      std::vector<Eigen::Vector3d>& velocity) const;
  void solveAsStuck(std::vector<ElasticContact>& contacts, const std::vector<std::size_t>& slot_of,
                    const std::vector<Eigen::Vector3d>& free_velocity);

  Blocks blocks_;
  Stuck stuck_;
};

}  // namespace ambf_like::detail
