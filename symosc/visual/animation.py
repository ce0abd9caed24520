"""Animations of simulated motions (matplotlib): frames at equal steps of simulated time.

:func:`animate_trajectory` turns a :class:`~symosc.mechanics.Trajectory` and a
:class:`~symosc.mechanics.Geometry` (points as expressions in the coordinates and time, lines between them) into an
:class:`Animation`: a JavaScript player in notebooks, a GIF through Pillow, an MP4 where ffmpeg is installed.
"""

from __future__ import annotations

import shutil
from pathlib import Path
from typing import Any

import numpy as np

from .._plotting import require_matplotlib
from .._printing import SymPyPrintable
from .._validate import check_finite_array, check_int, check_positive
from ..errors import ParameterError

__all__ = ["Animation", "animate_trajectory"]


class Animation(SymPyPrintable):
    """A matplotlib animation of a simulated motion.

    Frames are rendered by blitting on an Agg canvas (the background is drawn once), so a few hundred frames take
    a few seconds.  Made by :meth:`Trajectory.animate <symosc.mechanics.Trajectory.animate>`.

    Parameters
    ----------
    figure : matplotlib Figure
        The figure the frames are drawn on (Agg canvas).
    draw : callable
        ``draw(k)`` updates the moving artists to frame ``k`` and returns them.
    times : ndarray
        Simulated time of each frame.
    interval : float
        Milliseconds between frames.
    dpi : int
        Resolution of the frames.

    Attributes
    ----------
    frames : int
        Number of frames.
    interval : float
        Milliseconds between frames (the simulated time step divided by the playback speed).
    times : ndarray
        Simulated time of each frame.
    path : Path or None
        The file written by ``animate(path=...)`` or the last :meth:`save`.
    figure : matplotlib Figure
        The figure the frames are drawn on.

    Examples
    --------
    >>> import numpy as np
    >>> from symosc.models import n_link_pendulum
    >>> traj = n_link_pendulum(1).simulate(np.linspace(0, 1, 21), {"phi1": 0.4}, {"m1": 1, "l1": 1, "g": 9.81})
    >>> anim = traj.animate(fps=20)
    >>> anim.frames, round(anim.interval, 6)
    (21, 50.0)

    See Also
    --------
    symosc.mechanics.Trajectory.animate
    """

    def __init__(self, figure: Any, draw: Any, times: np.ndarray, interval: float, dpi: int) -> None:
        if not callable(getattr(figure, "savefig", None)):
            raise ParameterError(f"Animation(): figure must be a matplotlib Figure, got {figure!r}")
        if not callable(draw):
            raise ParameterError(f"Animation(): draw must be a function of the frame index, got {draw!r}")
        times = check_finite_array("times", times, ndim=1)
        if times.size == 0:
            raise ParameterError("Animation(): times must hold at least one frame time")
        interval = check_positive("interval", interval)
        dpi = check_int("dpi", dpi, minimum=1)
        self.figure, self._draw, self.times, self.interval = figure, draw, times, float(interval)
        self.frames = int(times.size)
        self.path: Path | None = None
        self._dpi = int(dpi)
        self._source: tuple | None = None  # (trajectory, options): what the animation is rebuilt from when unpickled

    def __reduce__(self) -> tuple:
        """Pickled as the trajectory and the options: the figure and its drawing function are rebuilt on loading."""
        if self._source is None:
            raise TypeError("this Animation was not made by Trajectory.animate and cannot be pickled")
        return (_rebuild, self._source)

    def __repr__(self) -> str:
        span = f"t = {self.times[0]:.4g} .. {self.times[-1]:.4g} s"
        return f"Animation({self.frames} frames, {1000.0 / self.interval:.3g} frames/s, {span})"

    def images(self) -> list:
        """The frames as RGB ``PIL.Image`` objects.

        Blitted: the axes, ticks and labels are drawn once, each frame draws only the moving lines and points; the
        time label is written with Pillow (matplotlib's text layout would be most of the cost of a frame).
        """
        from matplotlib.text import Text
        from PIL import Image, ImageDraw, ImageFont

        fig = self.figure
        fig.set_dpi(self._dpi)
        canvas = fig.canvas
        artists = self._draw(0)
        for a in artists:
            a.set_animated(True)
        canvas.draw()
        background = canvas.copy_from_bbox(fig.bbox)
        width, height = canvas.get_width_height()
        font = ImageFont.load_default(size=max(10, int(self._dpi * 0.15)))
        out = []
        for k in range(self.frames):
            artists = self._draw(k)
            canvas.restore_region(background)
            labels = []
            for a in artists:
                if isinstance(a, Text):
                    labels.append(a)
                else:
                    a.axes.draw_artist(a)
            image = Image.frombuffer("RGBA", (width, height), bytes(canvas.buffer_rgba())).convert("RGB")
            pen = ImageDraw.Draw(image)
            for a in labels:
                x, y = a.get_transform().transform(a.get_position())
                pen.text((x, height - y), a.get_text(), fill=(0, 0, 0), font=font)
            out.append(image)
        for a in artists:
            a.set_animated(False)
        return out

    def save(self, path: str | Path) -> Path:
        """Write the animation: ``.gif`` (Pillow), ``.mp4`` (ffmpeg) or ``.html`` (JavaScript player).

        Parameters
        ----------
        path : str or Path
            Target file; its suffix chooses the format.

        Returns
        -------
        Path
        """
        path = Path(path)
        suffix = path.suffix.lower()
        if suffix == ".gif":
            frames = _quantized(self.images())
            duration = max(round(self.interval), 20)  # GIF delays are in 10 ms units; browsers floor at 20 ms
            frames[0].save(path, save_all=True, append_images=frames[1:], duration=duration, loop=0, optimize=False)
        elif suffix == ".mp4":
            if shutil.which("ffmpeg") is None:
                raise ParameterError("writing .mp4 needs ffmpeg on the PATH (apt-get install ffmpeg); write a .gif")
            from matplotlib.animation import FFMpegWriter, FuncAnimation

            anim = FuncAnimation(self.figure, self._draw, frames=self.frames, interval=self.interval, blit=False)
            anim.save(path, writer=FFMpegWriter(fps=1000.0 / self.interval), dpi=self._dpi)
        elif suffix in (".html", ".htm"):
            path.write_text(self.to_jshtml(), encoding="utf-8")
        else:
            raise ParameterError(f"path must end in .gif, .mp4 or .html, got {path.name!r}")
        self.path = path
        return path

    def to_jshtml(self) -> str:
        """A self-contained HTML fragment: the frames (PNG, embedded) with play/pause buttons and a time slider."""
        import base64
        import io
        import uuid

        frames = []
        for im in _quantized(self.images()):
            buf = io.BytesIO()
            im.save(buf, format="PNG", compress_level=1)
            frames.append(base64.b64encode(buf.getvalue()).decode("ascii"))
        uid = "symosc" + uuid.uuid4().hex[:10]
        data = ",".join(f'"{f}"' for f in frames)
        times = ",".join(f"{t:.4f}" for t in self.times)
        return _PLAYER.format(uid=uid, data=data, times=times, interval=self.interval, last=self.frames - 1)

    def _repr_html_(self) -> str:
        return self.to_jshtml()


def _quantized(images: list) -> list:
    """RGB frames mapped to one shared 128-colour palette (taken from a montage of frames spread over the motion)."""
    from PIL import Image

    picks = [*images[:: max(1, len(images) // 6)][:6], images[-1]]
    w, h = images[0].size
    montage = Image.new("RGB", (w * len(picks), h))
    for i, im in enumerate(picks):
        montage.paste(im, (i * w, 0))
    palette = montage.quantize(colors=128, method=Image.Quantize.MEDIANCUT)
    return [im.quantize(palette=palette, dither=Image.Dither.NONE) for im in images]


_PLAYER = """<div class="symosc-animation" id="{uid}" style="display:inline-block;text-align:center">
<img id="{uid}-img" style="max-width:100%" alt="animation frame"><br>
<button id="{uid}-play" type="button">pause</button>
<input id="{uid}-slider" type="range" min="0" max="{last}" value="0" style="width:60%;vertical-align:middle">
<span id="{uid}-time" style="font-family:monospace"></span>
<script>
(function() {{
  var frames = [{data}], times = [{times}], k = 0, timer = null;
  var img = document.getElementById("{uid}-img"), slider = document.getElementById("{uid}-slider");
  var label = document.getElementById("{uid}-time"), button = document.getElementById("{uid}-play");
  function show(i) {{ k = i; img.src = "data:image/png;base64," + frames[k]; slider.value = k;
                     label.textContent = "t = " + times[k].toFixed(3) + " s"; }}
  function play() {{ timer = setInterval(function() {{ show((k + 1) % frames.length); }}, {interval});
                     button.textContent = "pause"; }}
  function pause() {{ clearInterval(timer); timer = null; button.textContent = "play"; }}
  button.onclick = function() {{ if (timer) pause(); else play(); }};
  slider.oninput = function() {{ pause(); show(parseInt(slider.value)); }};
  show(0); play();
}})();
</script></div>"""


def animate_trajectory(
    trajectory: Any,
    path: str | Path | None = None,
    *,
    fps: float = 25.0,
    speed: float = 1.0,
    max_frames: int = 400,
    trail: float = 0.0,
    geometry: Any = None,
    dpi: int = 80,
    size: float = 4.0,
) -> Animation:
    """Implementation of :meth:`Trajectory.animate <symosc.mechanics.Trajectory.animate>` (see there).

    Parameters
    ----------
    trajectory : Trajectory
        The simulated motion.
    path : str or Path, optional
        File to write (``.gif``, ``.mp4``, ``.html``).
    fps : float
        Frames per second.
    speed : float
        Simulated seconds per second of playback.
    max_frames : int
        Most frames to draw.
    trail : float
        Seconds of path drawn behind the last mass point.
    geometry : Geometry, optional
        Overrides the trajectory's geometry.
    dpi : int
        Resolution of written frames.
    size : float
        Figure size, inches.

    Returns
    -------
    Animation
    """
    require_matplotlib()
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.collections import LineCollection
    from matplotlib.figure import Figure

    if not all(hasattr(trajectory, a) for a in ("t", "states", "coordinates", "values", "geometry")):
        raise ParameterError(
            f"animate_trajectory(): trajectory must be a Trajectory (LagrangianSystem.simulate), got {trajectory!r}"
        )
    fps, speed = check_positive("fps", fps), check_positive("speed", speed)
    max_frames = check_int("max_frames", max_frames, minimum=2)
    trail = check_positive("trail", trail, allow_zero=True)
    geo = geometry if geometry is not None else trajectory.geometry
    if geo is None:
        raise ParameterError(
            "this trajectory has no geometry to draw: pass geometry=Geometry(points, lines) (points as expressions "
            "in the coordinates), or simulate a catalogue model (n_link_pendulum, body_on_springs)"
        )
    t = trajectory.t
    duration = float(t[-1] - t[0])
    count = int(min(max_frames, max(2, np.floor(duration * fps / speed) + 1)))
    times = np.linspace(t[0], t[-1], count)
    states = np.column_stack([np.interp(times, t, trajectory.states[:, i]) for i in range(trajectory.states.shape[1])])
    pos = geo.positions(times, states, trajectory.coordinates, trajectory.values)
    names = list(pos)
    index = {name: i for i, name in enumerate(names)}
    xy = np.stack([pos[name] for name in names], axis=1)  # (frames, points, 2)

    fig = Figure(figsize=(size, size), layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    lo, hi = np.nanmin(xy, axis=(0, 1)), np.nanmax(xy, axis=(0, 1))
    center, half = (lo + hi) / 2, max(float(np.max(hi - lo)) / 2, 1e-12) * 1.12
    ax.set_xlim(center[0] - half, center[0] + half)
    ax.set_ylim(center[1] - half, center[1] + half)
    ax.set_aspect("equal")
    ax.grid(True, lw=0.3, alpha=0.5)
    ax.set_xlabel("horizontal, m")
    ax.set_ylabel("vertical, m")
    pairs = [(index[a], index[b]) for a, b in geo.lines]
    links = LineCollection([], colors="0.2", linewidths=2.0, zorder=2)
    ax.add_collection(links)
    mass_idx = [index[m] for m in geo.masses]
    hinge_idx = [i for i in range(len(names)) if i not in mass_idx and not names[i].startswith("_")]
    (masses,) = ax.plot([], [], "o", color="C0", ms=9, zorder=3, label="bodies")
    (hinges,) = ax.plot([], [], "o", color="white", mec="0.2", ms=5, zorder=4)
    for name in geo.fixed:
        x0, y0 = xy[:, index[name]].mean(axis=0)
        ax.plot([x0 - 0.08 * half, x0 + 0.08 * half], [y0, y0], color="0.3", lw=3, zorder=1)
    (path_line,) = ax.plot([], [], "-", color="C1", lw=1.0, alpha=0.8, zorder=1)
    label = ax.text(0.02, 0.96, "", transform=ax.transAxes, va="top", family="monospace")
    step = float(times[1] - times[0]) if count > 1 else 0.0
    trail_frames = round(trail / step) if step > 0 and trail > 0 else 0
    end = mass_idx[-1] if mass_idx else len(names) - 1

    def draw(k: int) -> tuple:
        p = xy[k]
        links.set_segments([[p[a], p[b]] for a, b in pairs])
        masses.set_data(p[mass_idx, 0], p[mass_idx, 1])
        hinges.set_data(p[hinge_idx, 0], p[hinge_idx, 1])
        if trail_frames:
            s = max(0, k - trail_frames)
            path_line.set_data(xy[s : k + 1, end, 0], xy[s : k + 1, end, 1])
        label.set_text(f"t = {times[k]:7.3f} s")
        return links, masses, hinges, path_line, label

    interval = 1000.0 * step / speed if step > 0 else 1000.0 / fps
    out = Animation(fig, draw, times, interval, dpi)
    options = {"fps": fps, "speed": speed, "max_frames": max_frames, "trail": trail, "dpi": dpi, "size": size}
    out._source = (trajectory, {**options, "geometry": geometry})
    if path is not None:
        out.save(path)
    return out


def _rebuild(trajectory: Any, options: dict) -> Animation:
    return animate_trajectory(trajectory, None, **options)
