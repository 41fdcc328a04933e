"""Simulator node: steps the simulator at real_time_factor x wall time and publishes its state.

Publishes /clock, /map (latched), /odom (every physics step, 50 Hz) with odom -> base_footprint on
/tf, the fixed frames on /tf_static, /scan, /battery_state, /humans (and map -> human_<id> on /tf)
and /haven/events; subscribes /cmd_vel, /humans/<id>/cmd_vel and /haven/remove_obstruction; serves
/haven/reset and /haven/pause (std_srvs/SetBool: simulated time stands still, as Gazebo's
pause_physics; the web node pauses a trial a participant has dropped out of). It honours /haven/estop
itself, and warns once about each publisher on /cmd_vel beside the velocity mux (such as
teleop_twist_keyboard's default topic): it bypasses the mux's arbitration. The behaviour is
`haven_sim.sim.simulator.SimulatorComponent`; this node adds the wall-clock pacing (it is the
clock, so it must not wait on /clock itself). On the free-running clock it holds simulated time
within `control_lag_s` of what the controller has acted at (/haven/_pace): a busy machine slows
the clock (a `clock_held` event gives the factor achieved) instead of moving the robot on old
commands.
"""

from __future__ import annotations

import sys
from collections.abc import Sequence

from rclpy.clock import Clock, ClockType
from std_srvs.srv import SetBool, Trigger

from haven_sim.common import nodes, topics
from haven_sim.common.component import Message
from haven_sim.common.events import EventKind, Source, event
from haven_sim.nodes import wire
from haven_sim.nodes.component_node import ComponentNode
from haven_sim.nodes.lockstep import LockstepCoordinator
from haven_sim.nodes.runner import run_node
from haven_sim.runtime.lockstep import UNCAPPED_RTF
from haven_sim.sim.pacer import ControlPace, Pacer, WallClock
from haven_sim.sim.simulator import SimulatorComponent, SimulatorConfig
from haven_sim.sim.world import resolve_world_path
from haven_sim.sim.world_file import load_world

WRITERS_CHECK_S = 2.0  # wall seconds between looks at who publishes the robot's commands


HELD_SAID_BELOW = 0.9  # a free-running clock held below this share of the asked factor (over REPORT_S) is said


class SimNode(ComponentNode):
    def __init__(self, cli_args: Sequence[str] | None = None) -> None:
        super().__init__(nodes.SIM.name, cli_args)
        config = self.declare_config(SimulatorConfig)
        world = load_world(resolve_world_path(config.world))
        self.sim = SimulatorComponent(world, config)
        frames = wire.Frames(config.map_frame, config.odom_frame, config.base_frame, config.scan_frame)
        specs = wire.specs(frames, [h.id for h in world.humans])
        if topics.TF not in specs:
            self.get_logger().warning(
                "tf2_msgs is not installed: no /tf or /tf_static (run scripts/build_interfaces.py)"
            )
        self.wire(self.sim, specs, participant=False)
        self.create_service(Trigger, "haven/reset", self._on_reset)
        self.clock = WallClock()
        self.coordinator: LockstepCoordinator | None = None
        self.create_service(SetBool, "haven/pause", self._on_pause)
        self._bypassing: set[str] = set()  # publishers beside the mux, warned about once each
        self.create_timer(WRITERS_CHECK_S, self._check_writers, clock=Clock(clock_type=ClockType.STEADY_TIME))
        if self.lockstep_mode:
            self.coordinator = LockstepCoordinator(
                self,
                self.sim,
                list(config.lockstep_participants),
                list(config.lockstep_observers),
                list(config.lockstep_wait_for),
                config.real_time_factor,
                self._specs,
                self._pubs,
                self.lockstep_params,
                self.deferred,
                self.clock,
            )
            cap = (
                "as fast as they go"
                if config.real_time_factor >= UNCAPPED_RTF
                else f"at most {config.real_time_factor:g}x real time"
            )
            pace = f"lockstep with {', '.join(config.lockstep_participants) or 'no participants'}, {cap}"
        else:
            self.pacer = Pacer(config.sim.step_s, config.real_time_factor)
            self.pace = ControlPace(config.control_lag_s)
            pace_spec, ours = self._specs[topics.PACE], self.sole_writer(topics.PACE, nodes.MUX.name)
            self.create_subscription(
                pace_spec.msg_type, topics.PACE, lambda m: self._on_pace(pace_spec.decode(m), ours()), pace_spec.sub_qos
            )
            self.publish(self.sim.sense())
            self.create_timer(self.pacer.tick_period_s, self._tick, clock=Clock(clock_type=ClockType.STEADY_TIME))
            pace = f"{config.real_time_factor:g}x real time"
        self.get_logger().info(
            f"world '{world.name}' from {world.source}: robot {config.sim.robot.name}, {len(world.humans)} human(s), "
            f"{config.sim.physics_rate_hz:g} Hz physics, {pace}"
        )

    def now(self) -> float:
        """The simulator's own time (it is the clock)."""
        return self.sim.sim.time

    def _tick(self) -> None:
        if self.clock.paused:  # (not even the steps a busy machine still owes)
            return
        wall, step_s = self.clock.now(), self.pacer.step_s
        allowed = self.pace.allowed_steps(self.sim.sim.time, step_s, wall)
        for _ in range(self.pacer.due_steps(wall, allowed)):
            self.sim.advance()
            self.publish(self.sim.sense())
        achieved = self.pace.factor(self.sim.sim.time, wall, self.pacer.holding)
        requested = self.pacer.real_time_factor
        if achieved is not None and achieved < HELD_SAID_BELOW * requested:
            now = self.sim.sim.time
            self.get_logger().warning(
                f"sim time ran at {achieved:.2f}x real time over the last {self.pace.REPORT_S:g} s (asked: "
                f"{requested:g}x): held for the controller, which fell behind (a busy machine)"
            )
            held = event(
                EventKind.CLOCK_HELD, now, Source.SIM, real_time_factor=round(achieved, 3), requested=requested
            )
            self.publish([Message(topics.EVENTS, held, now)])

    def _on_pace(self, acted_at: float, ours: bool) -> None:
        """The controller's pace, passed on by our mux; while anybody else publishes there too, the
        clock is held by nobody (an outside node must not stand simulated time still)."""
        self.pace.report(acted_at if ours else topics.PACE_IDLE, self.clock.now())

    def _check_writers(self) -> None:
        topic = self.resolve_topic_name(topics.CMD_VEL)
        infos = self.get_publishers_info_by_topic(topic)
        if any(i.node_name == nodes.UNNAMED for i in infos):
            return  # (a writer whose node's name discovery has not brought yet: named at a later look)
        writers = {f"{i.node_namespace.rstrip('/')}/{i.node_name}" for i in infos}
        if len(writers) < 2:
            return
        for name in sorted(writers - {f"/{nodes.MUX.name}"} - self._bypassing):
            self._bypassing.add(name)
            self.get_logger().warning(
                f"{name} publishes on {topic} beside the velocity mux: it bypasses the mux (teleop, "
                f"navigation, e-stop); publish on /{topics.CMD_VEL_TELEOP} instead "
                f"(teleop_twist_keyboard: --ros-args -r cmd_vel:={topics.CMD_VEL_TELEOP}). "
                "The e-stop still holds: the simulator honours /haven/estop itself."
            )

    def _on_pause(self, request: SetBool.Request, response: SetBool.Response) -> SetBool.Response:
        """Pause (data true) or resume simulated time; a `trial_paused` / `trial_resumed` event."""
        now = self.sim.sim.time
        if request.data:
            response.success = self.clock.pause()
            response.message = f"paused at t={now:.2f} s" if response.success else "already paused"
            if response.success:
                self.emit([Message(topics.EVENTS, event(EventKind.TRIAL_PAUSED, now, Source.SIM), now)])
        else:
            stood = self.clock.resume()
            response.success = stood is not None
            response.message = f"resumed at t={now:.2f} s after {stood:.1f} s" if stood is not None else "not paused"
            if stood is not None:
                self.emit(
                    [
                        Message(
                            topics.EVENTS,
                            event(EventKind.TRIAL_RESUMED, now, Source.SIM, paused_s=round(stood, 2)),
                            now,
                        )
                    ]
                )
                if self.coordinator is not None:
                    self.coordinator.resumed()
        self.get_logger().info(f"/haven/pause: {response.message}")
        return response

    def _on_reset(self, request: Trigger.Request, response: Trigger.Response) -> Trigger.Response:
        if not self.sim.config.reset_allowed:
            response.success = False
            response.message = (
                "refused: this simulator runs a recorded trial (haven run); /haven/reset is for haven sim"
            )
            self.get_logger().warning(f"/haven/reset {response.message}", throttle_duration_sec=2.0)
            self.emit([self.refused_request("service", "/haven/reset", response.message)])
            return response
        self.sim.reset()
        self.publish(self.sim.sense())
        response.success = True
        response.message = f"world '{self.sim.world.name}' reset at t={self.sim.sim.time:.2f} s"
        return response


def main(args: list[str] | None = None) -> None:
    sys.exit(run_node(SimNode, args))


if __name__ == "__main__":
    main()
