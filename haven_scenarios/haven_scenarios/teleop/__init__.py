"""Keyboard and scripted driving of the robot or a participant: key maps, what a teleop client is told, the demo
square."""
