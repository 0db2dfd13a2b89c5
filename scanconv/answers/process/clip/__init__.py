"""The clipping answers: Cohen-Sutherland and Liang-Barsky (`rectangle`), Cyrus-Beck,
Nicholl-Lee-Nicholl, midpoint subdivision, and the polygon clippers (Sutherland-Hodgman,
Weiler-Atherton)."""
