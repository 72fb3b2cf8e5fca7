"""raven_sim: the Raven-II twin in process, at C++ speed.

    import raven_sim                                  # with build/python on PYTHONPATH
    twin = raven_sim.Twin()                           # our Raven-II, simulated clock
    twin.enable_and_home()
    q = twin.setpoint_js(raven_sim.Arm.LEFT).position
    q[0] += 0.02
    twin.send(raven_sim.ServoJp(raven_sim.Arm.LEFT, q))
    twin.advance(0.1)                                 # 100 robot cycles

The same command objects and results as the C++ RavenPlatform; errors keep their messages
(LoadError names file, line and key). World loads AMBF's files; read_ci / read_rs / RsWriter
handle the paper's recordings; estimate_forces reads a recording's motor signals back into
the forces behind them (docs/forces.md); PegTransferEnv is the peg transfer as a learning environment;
RobotOverRos the robot (or a twin node) over ROS as a policy meets it (docs/learning.md).
"""

from ._raven_sim import (Arm, CommandResult, Controller, ControllerSession, Mode, GrasperForces, JointSample, LoadError, MoveJp,
                         OperatingStatus, PegCameras, PegTransferCore, PegTransferStep, RavenState,
                         RecordingError, RobotOverRos, RsRecording, RsWriter, ServoCp, ServoCr, ServoJawJp,
                         SimulationDiverged, estimate_forces,
                         ServoJawJr, ServoJp, ServoJr, StateCommand, Twin, World, ci_columns,
                         observation_layout, peg_layout, read_ci, read_rs, ring_placed, task_camera, tool_points,
                         write_ci)
from .env import SEGMENT_IDS, PegTransferEnv, VectorPegTransferEnv, part
