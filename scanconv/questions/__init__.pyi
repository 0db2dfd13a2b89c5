# The public names of scanconv.questions, for type checkers and at run time (the package
# loads each on first use from this list: scanconv._attach_stub).
from .answering import answer as answer
from .answering import answered as answered
from .answering import shown_with as shown_with
from .answering import solve as solve
from .budget import check_budget as check_budget
from .files import QuestionError as QuestionError
from .files import read_file as read_file
from .files import read_questions as read_questions
from .marking import check as check
from .marking import marking_question as marking_question
from .parser import CommandLine as CommandLine
from .parser import parse as parse
from .words import UsageError as UsageError

__all__ = [
    "CommandLine",
    "QuestionError",
    "UsageError",
    "answer",
    "answered",
    "check",
    "check_budget",
    "marking_question",
    "parse",
    "read_file",
    "read_questions",
    "shown_with",
    "solve",
]
