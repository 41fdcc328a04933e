"""A Likert questionnaire on trust in the robot, asked in the participant's page after a trial
(three items adapted for illustration; cite the instrument you actually use)."""

TRUST = {
    "title": "Trust in the robot",
    "points": 7,
    "anchors": ["Strongly disagree", "Strongly agree"],
    "items": [
        {"id": "rely", "text": "I could rely on the robot to let me pass."},
        {"id": "predict", "text": "I could predict what the robot would do."},
        {"id": "wary", "text": "I was wary of the robot.", "reverse": True},
    ],
}
