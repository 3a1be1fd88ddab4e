"""What grading produces: a score and feedback per criterion, per submission."""

from __future__ import annotations

from pkgtool.records import record


@record
class CriterionResult:
    """One rubric criterion's outcome; ``feedback`` lines are meant for the student."""

    name: str
    kind: str
    score: float
    max_score: float
    feedback: tuple[str, ...] = ()
    output: str = ""
    visibility: str = "visible"

    @property
    def passed(self) -> bool:
        """True at full marks."""
        return self.score >= self.max_score


@record
class SubmissionResult:
    """One graded submission.

    ``error`` says why it could not be graded at all (an unsafe archive, no package);
    ``unchanged`` is True when the submission on disk hashed the same after grading as before.
    """

    label: str
    path: str
    score: float
    max_score: float
    criteria: tuple[CriterionResult, ...]
    package: str | None = None
    error: str | None = None
    isolation: str = ""
    seconds: float = 0.0
    unchanged: bool = True
