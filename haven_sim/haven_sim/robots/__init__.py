"""Robots: the description every part of the suite reads, robot files, the `haven.robots` plugin
kind and HAVEN's catalogue."""
