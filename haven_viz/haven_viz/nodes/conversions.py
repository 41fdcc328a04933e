"""MarkerSpec -> visualization_msgs/Marker, CueState -> JSON: the only place haven_viz builds messages."""

from __future__ import annotations

from typing import Any

from geometry_msgs.msg import Point
from std_msgs.msg import ColorRGBA, String
from visualization_msgs.msg import Marker, MarkerArray

from haven_sim.common import topics
from haven_sim.common.geometry import quaternion_to_yaw
from haven_sim.nodes import qos
from haven_sim.nodes.conversions import quaternion_msg, time_msg
from haven_sim.nodes.wire import TopicSpec
from haven_viz.cues import CueState
from haven_viz.markers import MarkerSpec, Shape, Update


def marker_msg(m: MarkerSpec, stamp: float, frame_id: str = "map") -> Marker:
    msg = Marker()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.ns = m.ns
    msg.id = m.id
    msg.type = m.shape.value
    msg.action = Marker.ADD
    msg.pose.position.x, msg.pose.position.y, msg.pose.position.z = m.position
    msg.pose.orientation = quaternion_msg(m.yaw)
    msg.scale.x, msg.scale.y, msg.scale.z = m.scale
    msg.color = ColorRGBA(r=m.color[0], g=m.color[1], b=m.color[2], a=m.color[3])
    msg.text = m.text
    msg.points = [Point(x=p[0], y=p[1], z=p[2]) for p in m.points]
    return msg


def delete_msg(ns: str, marker_id: int, stamp: float, frame_id: str = "map") -> Marker:
    msg = Marker()
    msg.header.stamp = time_msg(stamp)
    msg.header.frame_id = frame_id
    msg.ns = ns
    msg.id = marker_id
    msg.action = Marker.DELETE
    return msg


def marker_array(update: Update, stamp: float, frame_id: str = "map") -> MarkerArray:
    msg = MarkerArray()
    msg.markers = [delete_msg(ns, i, stamp, frame_id) for ns, i in update.delete]
    msg.markers += [marker_msg(m, stamp, frame_id) for m in update.upsert]
    return msg


def spec_from_msg(msg: Marker) -> MarkerSpec:
    """The inverse of marker_msg (for tests and tools that read markers back)."""
    q = msg.pose.orientation
    return MarkerSpec(
        msg.ns,
        msg.id,
        Shape(msg.type),
        (msg.pose.position.x, msg.pose.position.y, msg.pose.position.z),
        quaternion_to_yaw(q.x, q.y, q.z, q.w),
        (msg.scale.x, msg.scale.y, msg.scale.z),
        (msg.color.r, msg.color.g, msg.color.b, msg.color.a),
        msg.text,
        tuple((p.x, p.y, p.z) for p in msg.points),
    )


def _no_reader(msg: Any) -> Any:
    raise ValueError("no HAVEN node reads this topic")


def viz_specs(frame_id: str = "map") -> dict[str, TopicSpec]:
    """haven_viz's topics for the topic table (haven_sim.nodes.wire)."""
    return {
        topics.AR_MARKERS: TopicSpec(
            MarkerArray, lambda u, t: marker_array(u, t, frame_id), _no_reader, qos.STREAM, qos.RELIABLE
        ),
        topics.WORLD_MARKERS: TopicSpec(
            MarkerArray, lambda u, t: marker_array(u, t, frame_id), _no_reader, qos.LATCHED, qos.LATCHED
        ),
        topics.CUE_STATE: TopicSpec(
            String,
            lambda c, t: String(data=c.to_json(t)),
            lambda m: CueState.from_json(m.data)[1],
            qos.CHANGES,
            qos.LATCHED,
        ),
    }
