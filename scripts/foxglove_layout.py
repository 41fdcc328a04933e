"""Writes haven_viz/haven_viz/foxglove/haven_layout.json with foxglove-sdk's layout API, so the
layout is valid by construction: a 3D panel in frame `map` with the map, world markers, AR cues,
plan, scan, odometry and humans; beside it the events log and the viz node's parameters (the cue
toggles). Run: python scripts/foxglove_layout.py (needs `pip install foxglove-sdk`)."""

from pathlib import Path

from foxglove import layouts as L

OUT = Path(__file__).resolve().parents[1] / "haven_viz" / "haven_viz" / "foxglove" / "haven_layout.json"


def build() -> L.Layout:
    topics = {
        "/map": L.BaseRendererRosOccupancyGridTopicSettings(visible=True, alpha=0.6),
        "/haven/world_markers": L.BaseRendererRosMarkerTopicSettings(visible=True),
        "/haven/ar_markers": L.BaseRendererRosMarkerTopicSettings(visible=True),
        "/plan": L.BaseRendererPosesTopicSettings(visible=True),
        "/scan": L.BaseRendererLaserScanTopicSettings(
            visible=True, point_size=4, color_mode="flat", flat_color="#ff3333"
        ),
        "/odom": L.BaseRendererPoseTopicSettings(visible=True, type="arrow"),
        "/humans": L.BaseRendererPosesTopicSettings(visible=True),
    }
    scene = L.ThreeDeePanel(
        title="HAVEN",
        config=L.ThreeDeeConfig(
            topics=topics,
            fixed_frame="map",
            follow_mode="follow-none",
            camera_state=L.ThreeDeeCameraState(
                distance=14, perspective=True, phi=50, target=[4.0, 2.5, 0.0], theta_offset=0
            ),
            publish=L.ThreeDeePublishSettings(type="pose", pose_topic="/goal_pose"),
        ),
    )
    side = L.SplitContainer(
        direction="column",
        items=[
            L.SplitItem(
                proportion=2,
                content=L.RawMessagesPanel(title="Events", config=L.RawMessagesConfig(topic_path="/haven/events")),
            ),
            L.SplitItem(proportion=1, content=L.ParametersPanel(title="Cue toggles (viz node)")),
        ],
    )
    items = [L.SplitItem(proportion=3, content=scene), L.SplitItem(proportion=1, content=side)]
    return L.Layout(content=L.SplitContainer(direction="row", items=items))


if __name__ == "__main__":
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text(build().to_json() + "\n")
    print(f"wrote {OUT}")
