# top-level comment in every block
{% block imports %}import x{% endblock %}
{% block body %}body{% endblock %}
