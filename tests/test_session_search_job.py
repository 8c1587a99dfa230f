"""SIMULATE run by a driver off the session's thread (`SearchJob`): its result, offered to the session as a
`Searched` entry, is what the session would find itself and what a replay of the journal finds; a stopped search
keeps its best as the search of the rollouts it ran; an offer for another document is not taken."""

from __future__ import annotations

import math
import threading
from dataclasses import replace
from pathlib import Path

from test_session_modes import live, replayed
from test_session_simulate import load, wall_out_of_the_way

from physink_tui.formats.journal.reader import read_journal
from physink_tui.session import simulation
from physink_tui.session.search_job import Progress, SearchJob
from physink_tui.session.session import Session
from physink_tui.sim.evaluate import evaluate_problem
from tests.sim_scenes import CANVAS, demonstration


def loaded(tmp_path: Path, scene=None) -> Session:
    """A session with the demonstrated ball loaded (the project's JSON rounds numbers: search what it holds)."""
    return live([load(timeline=demonstration(), scene=scene)], tmp_path / "loaded.physink.jsonl")


def test_a_finished_job_is_what_the_session_and_a_replay_find(tmp_path: Path) -> None:
    document = loaded(tmp_path, wall_out_of_the_way()).document  # not found: the whole budget is searched
    seen: list[Progress] = []
    job = SearchJob(document.scene, document.timeline, CANVAS, 3, 6, on_progress=seen.append)
    offer = job.run()
    assert offer is not None and offer.result == simulation.run(document.scene, document.timeline, CANVAS, 3, 6)
    assert [p.rollouts for p in seen] == list(range(7)) and all(p.budget == 6 for p in seen)
    assert math.isinf(seen[0].qualitative) and math.isfinite(seen[-1].quantitative)
    path = tmp_path / "s.physink.jsonl"
    session = live([load(timeline=demonstration(), scene=wall_out_of_the_way()), replace(offer, t=1.0)], path)
    assert session.view().search == offer.result and not session.errors
    assert [e.args for e in read_journal(path).entries if e.name == "simulate"] == [(3, 6)]
    assert replayed(path).view().search == offer.result


def test_a_stopped_job_keeps_the_best_so_far_as_the_search_of_the_rollouts_it_ran(tmp_path: Path) -> None:
    document = loaded(tmp_path, wall_out_of_the_way()).document
    calls = []

    def evaluate(problem, candidate):
        calls.append(candidate)
        if len(calls) == 4:
            job.stop()  # as a cancel from another thread during the fourth rollout
        return evaluate_problem(problem, candidate)

    job = SearchJob(document.scene, document.timeline, CANVAS, 3, 50, evaluate=evaluate)
    offer = job.run()
    assert offer is not None and len(calls) == 4 and job.stopped
    assert (offer.budget, offer.result.rollouts, offer.result.budget) == (4, 4, 4)
    assert offer.result == simulation.run(document.scene, document.timeline, CANVAS, 3, 4)
    path = tmp_path / "s.physink.jsonl"
    live([load(timeline=demonstration(), scene=wall_out_of_the_way()), replace(offer, t=1.0)], path)
    assert [e.args for e in read_journal(path).entries if e.name == "simulate"] == [(3, 4)]
    assert replayed(path).view().search == offer.result


def test_a_job_stopped_before_its_first_rollout_offers_nothing(tmp_path: Path) -> None:
    document = loaded(tmp_path).document
    job = SearchJob(document.scene, document.timeline, CANVAS, 0, 5)
    job.stop()
    assert job.run() is None and job.rollouts == 0


def test_an_offer_is_taken_only_for_the_document_it_searched(tmp_path: Path) -> None:
    document = loaded(tmp_path).document
    offer = SearchJob(document.scene, document.timeline, CANVAS, 0, 3).run()
    assert offer is not None
    marked = replace(offer, result=replace(offer.result, rollouts=99), t=1.0)  # tells the offer's use apart
    taken = live([load(timeline=demonstration()), marked], tmp_path / "a.physink.jsonl")
    assert taken.view().search.rollouts == 99
    elsewhere = live([load(timeline=demonstration(), scene=wall_out_of_the_way()), marked],
                     tmp_path / "b.physink.jsonl")
    assert elsewhere.view().search is not None and elsewhere.view().search.rollouts <= 3


def test_stop_from_another_thread_ends_a_running_job(tmp_path: Path) -> None:
    document = loaded(tmp_path, wall_out_of_the_way()).document
    started = threading.Event()

    def evaluate(problem, candidate):
        started.set()
        return evaluate_problem(problem, candidate)

    job = SearchJob(document.scene, document.timeline, CANVAS, 3, 10_000, evaluate=evaluate)
    result: list = []
    thread = threading.Thread(target=lambda: result.append(job.run()))
    thread.start()
    assert started.wait(30)
    job.stop()
    thread.join(60)
    assert not thread.is_alive() and result[0] is not None and 1 <= result[0].budget < 10_000
