<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" simplifyAlgorithm="0" simplifyLocal="1" version="3.22.16-Białowieża" minScale="100000000" simplifyDrawingHints="1" labelsEnabled="0" hasScaleBasedVisibilityFlag="0" maxScale="0" symbologyReferenceScale="-1" simplifyDrawingTol="1" simplifyMaxScale="1">
  <renderer-v2 referencescale="-1" attr="polarity" enableorderby="0" type="categorizedSymbol" forceraster="0" symbollevels="0">
    <categories>
      <category render="true" label="Warm by day" symbol="0" value="hot"/>
      <category render="true" label="Cool by day" symbol="1" value="cold"/>
    </categories>
    <symbols>
      <symbol type="fill" force_rhr="0" clip_to_extent="1" name="0" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" name="name" value=""/>
            <Option name="properties"/>
            <Option type="QString" name="type" value="collection"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleFill" locked="0" pass="0">
          <Option type="Map">
            <Option type="QString" name="border_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="color" value="0,0,0,0"/>
            <Option type="QString" name="joinstyle" value="bevel"/>
            <Option type="QString" name="offset" value="0,0"/>
            <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="offset_unit" value="MM"/>
            <Option type="QString" name="outline_color" value="215,48,39,255"/>
            <Option type="QString" name="outline_style" value="solid"/>
            <Option type="QString" name="outline_width" value="0.5"/>
            <Option type="QString" name="outline_width_unit" value="MM"/>
            <Option type="QString" name="style" value="no"/>
          </Option>
          <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
          <prop v="0,0,0,0" k="color"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="215,48,39,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.5" k="outline_width"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="no" k="style"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="fill" force_rhr="0" clip_to_extent="1" name="1" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option type="QString" name="name" value=""/>
            <Option name="properties"/>
            <Option type="QString" name="type" value="collection"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleFill" locked="0" pass="0">
          <Option type="Map">
            <Option type="QString" name="border_width_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="color" value="0,0,0,0"/>
            <Option type="QString" name="joinstyle" value="bevel"/>
            <Option type="QString" name="offset" value="0,0"/>
            <Option type="QString" name="offset_map_unit_scale" value="3x:0,0,0,0,0,0"/>
            <Option type="QString" name="offset_unit" value="MM"/>
            <Option type="QString" name="outline_color" value="69,117,180,255"/>
            <Option type="QString" name="outline_style" value="solid"/>
            <Option type="QString" name="outline_width" value="0.5"/>
            <Option type="QString" name="outline_width_unit" value="MM"/>
            <Option type="QString" name="style" value="no"/>
          </Option>
          <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
          <prop v="0,0,0,0" k="color"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="69,117,180,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.5" k="outline_width"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="no" k="style"/>
          <data_defined_properties>
            <Option type="Map">
              <Option type="QString" name="name" value=""/>
              <Option name="properties"/>
              <Option type="QString" name="type" value="collection"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
    </symbols>
    <rotation/>
    <sizescale/>
  </renderer-v2>
  <blendMode>0</blendMode>
  <featureBlendMode>0</featureBlendMode>
  <layerOpacity>1</layerOpacity>
  <fieldConfiguration>
    <field configurationFlags="None" name="anomaly_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="x">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="y">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lat">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="7"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lon">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="7"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="area_m2">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diameter_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="circularity">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_sigma_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="3"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_sigma_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="status">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="polarity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="class_cue">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="p_mine">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="priority">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="set_aside_reason">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="n_scans">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_day_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_night_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="mine_curve_r">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="mine_curve_level">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option type="bool" name="AllowNull" value="true"/>
            <Option type="double" name="Max" value="1e+09"/>
            <Option type="double" name="Min" value="-1e+09"/>
            <Option type="int" name="Precision" value="2"/>
            <Option type="int" name="Step" value="1"/>
            <Option type="QString" name="Style" value="SpinBox"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="fix_quality">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="figure">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_series">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="short_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="likelihood">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence_pct">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option type="bool" name="IsMultiline" value="false"/>
            <Option type="bool" name="UseHtml" value="false"/>
          </Option>
        </config>
      </editWidget>
    </field>
  </fieldConfiguration>
  <aliases>
    <alias field="anomaly_id" index="0" name="Suspect id"/>
    <alias field="x" index="1" name="Easting (m, survey UTM)"/>
    <alias field="y" index="2" name="Northing (m, survey UTM)"/>
    <alias field="lat" index="3" name="Latitude (°, WGS84)"/>
    <alias field="lon" index="4" name="Longitude (°, WGS84)"/>
    <alias field="area_m2" index="5" name="Area (m²)"/>
    <alias field="diameter_m" index="6" name="Diameter (m)"/>
    <alias field="circularity" index="7" name="Circularity (0-1)"/>
    <alias field="depth_m" index="8" name="Burial depth (m)"/>
    <alias field="depth_sigma_m" index="9" name="Depth uncertainty, 1σ (m)"/>
    <alias field="diffusivity_m2s" index="10" name="Thermal diffusivity (m²/s)"/>
    <alias field="diffusivity_sigma_m2s" index="11" name="Diffusivity uncertainty, 1σ (m²/s)"/>
    <alias field="status" index="12" name="Characterisation status"/>
    <alias field="polarity" index="13" name="Polarity"/>
    <alias field="class_cue" index="14" name="Class cue"/>
    <alias field="cue_confidence" index="15" name="Class cue confidence (0-1)"/>
    <alias field="p_mine" index="16" name="Mine likelihood (0-1)"/>
    <alias field="priority" index="17" name="Priority (1 = first)"/>
    <alias field="set_aside_reason" index="18" name="Set aside because"/>
    <alias field="n_scans" index="19" name="Scans seen"/>
    <alias field="contrast_day_k" index="20" name="Day contrast (K)"/>
    <alias field="contrast_night_k" index="21" name="Night contrast (K)"/>
    <alias field="mine_curve_r" index="22" name="Match with a mine's diurnal curve (-1 to 1)"/>
    <alias field="mine_curve_level" index="23" name="Offset from a mine's diurnal curve (swings)"/>
    <alias field="fix_quality" index="24" name="GNSS fix quality"/>
    <alias field="figure" index="25" name="Contrast curve"/>
    <alias field="contrast_series" index="26" name="Contrast series (JSON)"/>
    <alias field="short_id" index="27" name="Short id"/>
    <alias field="depth" index="28" name="Burial depth ± 1σ"/>
    <alias field="diffusivity" index="29" name="Thermal diffusivity ± 1σ"/>
    <alias field="likelihood" index="30" name="Mine likelihood"/>
    <alias field="cue_confidence_pct" index="31" name="Class cue confidence"/>
  </aliases>
  <defaults>
    <default field="anomaly_id" expression="" applyOnUpdate="0"/>
    <default field="x" expression="" applyOnUpdate="0"/>
    <default field="y" expression="" applyOnUpdate="0"/>
    <default field="lat" expression="" applyOnUpdate="0"/>
    <default field="lon" expression="" applyOnUpdate="0"/>
    <default field="area_m2" expression="" applyOnUpdate="0"/>
    <default field="diameter_m" expression="" applyOnUpdate="0"/>
    <default field="circularity" expression="" applyOnUpdate="0"/>
    <default field="depth_m" expression="" applyOnUpdate="0"/>
    <default field="depth_sigma_m" expression="" applyOnUpdate="0"/>
    <default field="diffusivity_m2s" expression="" applyOnUpdate="0"/>
    <default field="diffusivity_sigma_m2s" expression="" applyOnUpdate="0"/>
    <default field="status" expression="" applyOnUpdate="0"/>
    <default field="polarity" expression="" applyOnUpdate="0"/>
    <default field="class_cue" expression="" applyOnUpdate="0"/>
    <default field="cue_confidence" expression="" applyOnUpdate="0"/>
    <default field="p_mine" expression="" applyOnUpdate="0"/>
    <default field="priority" expression="" applyOnUpdate="0"/>
    <default field="set_aside_reason" expression="" applyOnUpdate="0"/>
    <default field="n_scans" expression="" applyOnUpdate="0"/>
    <default field="contrast_day_k" expression="" applyOnUpdate="0"/>
    <default field="contrast_night_k" expression="" applyOnUpdate="0"/>
    <default field="mine_curve_r" expression="" applyOnUpdate="0"/>
    <default field="mine_curve_level" expression="" applyOnUpdate="0"/>
    <default field="fix_quality" expression="" applyOnUpdate="0"/>
    <default field="figure" expression="" applyOnUpdate="0"/>
    <default field="contrast_series" expression="" applyOnUpdate="0"/>
    <default field="short_id" expression="" applyOnUpdate="0"/>
    <default field="depth" expression="" applyOnUpdate="0"/>
    <default field="diffusivity" expression="" applyOnUpdate="0"/>
    <default field="likelihood" expression="" applyOnUpdate="0"/>
    <default field="cue_confidence_pct" expression="" applyOnUpdate="0"/>
  </defaults>
  <constraints>
    <constraint exp_strength="0" field="anomaly_id" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="x" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="y" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="lat" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="lon" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="area_m2" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="diameter_m" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="circularity" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="depth_m" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="depth_sigma_m" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="diffusivity_m2s" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="diffusivity_sigma_m2s" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="status" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="polarity" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="class_cue" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="cue_confidence" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="p_mine" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="priority" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="set_aside_reason" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="n_scans" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="contrast_day_k" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="contrast_night_k" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="mine_curve_r" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="mine_curve_level" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="fix_quality" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="figure" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="contrast_series" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="short_id" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="depth" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="diffusivity" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="likelihood" notnull_strength="0" constraints="0" unique_strength="0"/>
    <constraint exp_strength="0" field="cue_confidence_pct" notnull_strength="0" constraints="0" unique_strength="0"/>
  </constraints>
  <constraintExpressions>
    <constraint field="anomaly_id" exp="" desc=""/>
    <constraint field="x" exp="" desc=""/>
    <constraint field="y" exp="" desc=""/>
    <constraint field="lat" exp="" desc=""/>
    <constraint field="lon" exp="" desc=""/>
    <constraint field="area_m2" exp="" desc=""/>
    <constraint field="diameter_m" exp="" desc=""/>
    <constraint field="circularity" exp="" desc=""/>
    <constraint field="depth_m" exp="" desc=""/>
    <constraint field="depth_sigma_m" exp="" desc=""/>
    <constraint field="diffusivity_m2s" exp="" desc=""/>
    <constraint field="diffusivity_sigma_m2s" exp="" desc=""/>
    <constraint field="status" exp="" desc=""/>
    <constraint field="polarity" exp="" desc=""/>
    <constraint field="class_cue" exp="" desc=""/>
    <constraint field="cue_confidence" exp="" desc=""/>
    <constraint field="p_mine" exp="" desc=""/>
    <constraint field="priority" exp="" desc=""/>
    <constraint field="set_aside_reason" exp="" desc=""/>
    <constraint field="n_scans" exp="" desc=""/>
    <constraint field="contrast_day_k" exp="" desc=""/>
    <constraint field="contrast_night_k" exp="" desc=""/>
    <constraint field="mine_curve_r" exp="" desc=""/>
    <constraint field="mine_curve_level" exp="" desc=""/>
    <constraint field="fix_quality" exp="" desc=""/>
    <constraint field="figure" exp="" desc=""/>
    <constraint field="contrast_series" exp="" desc=""/>
    <constraint field="short_id" exp="" desc=""/>
    <constraint field="depth" exp="" desc=""/>
    <constraint field="diffusivity" exp="" desc=""/>
    <constraint field="likelihood" exp="" desc=""/>
    <constraint field="cue_confidence_pct" exp="" desc=""/>
  </constraintExpressions>
  <expressionfields>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" name="short_id"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" name="depth"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" name="diffusivity"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" name="likelihood"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" name="cue_confidence_pct"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" name="short_id"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" name="depth"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" name="diffusivity"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" name="likelihood"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" name="cue_confidence_pct"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" name="short_id"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" name="depth"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" name="diffusivity"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" name="likelihood"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" name="cue_confidence_pct"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" name="short_id"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" name="depth"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" name="diffusivity"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" name="likelihood"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" name="cue_confidence_pct"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" name="short_id"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" name="depth"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" name="diffusivity"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" name="likelihood"/>
    <field precision="0" typeName="" length="0" comment="" type="10" subType="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" name="cue_confidence_pct"/>
  </expressionfields>
  <attributetableconfig actionWidgetStyle="dropDown" sortOrder="0" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))">
    <columns>
      <column hidden="0" width="-1" type="field" name="anomaly_id"/>
      <column hidden="0" width="-1" type="field" name="polarity"/>
      <column hidden="0" width="-1" type="field" name="area_m2"/>
      <column hidden="0" width="-1" type="field" name="p_mine"/>
      <column hidden="0" width="-1" type="field" name="priority"/>
      <column hidden="0" width="-1" type="field" name="cue_confidence"/>
      <column hidden="0" width="-1" type="field" name="set_aside_reason"/>
      <column hidden="0" width="-1" type="field" name="short_id"/>
      <column hidden="0" width="-1" type="field" name="depth"/>
      <column hidden="0" width="-1" type="field" name="diffusivity"/>
      <column hidden="0" width="-1" type="field" name="likelihood"/>
      <column hidden="0" width="-1" type="field" name="cue_confidence_pct"/>
      <column hidden="1" width="-1" type="actions"/>
    </columns>
  </attributetableconfig>
  <conditionalstyles>
    <rowstyles/>
    <fieldstyles/>
  </conditionalstyles>
  <storedexpressions/>
  <editform tolerant="1"></editform>
  <editforminit/>
  <editforminitcodesource>0</editforminitcodesource>
  <editforminitfilepath></editforminitfilepath>
  <editforminitcode><![CDATA[]]></editforminitcode>
  <featformsuppress>0</featformsuppress>
  <editorlayout>tablayout</editorlayout>
  <attributeEditorForm>
    <attributeEditorContainer columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" name="Suspect" visibilityExpression="">
      <attributeEditorContainer columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" name="Identification" visibilityExpression="">
        <attributeEditorField showLabel="1" index="27" name="short_id"/>
        <attributeEditorField showLabel="1" index="0" name="anomaly_id"/>
        <attributeEditorField showLabel="1" index="17" name="priority"/>
        <attributeEditorField showLabel="1" index="14" name="class_cue"/>
        <attributeEditorField showLabel="1" index="30" name="likelihood"/>
        <attributeEditorField showLabel="1" index="31" name="cue_confidence_pct"/>
        <attributeEditorField showLabel="1" index="12" name="status"/>
        <attributeEditorField showLabel="1" index="13" name="polarity"/>
        <attributeEditorField showLabel="1" index="18" name="set_aside_reason"/>
      </attributeEditorContainer>
      <attributeEditorContainer columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" name="Burial depth and soil" visibilityExpression="">
        <attributeEditorField showLabel="1" index="28" name="depth"/>
        <attributeEditorField showLabel="1" index="29" name="diffusivity"/>
      </attributeEditorContainer>
      <attributeEditorContainer columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" name="Thermal contrast" visibilityExpression="">
        <attributeEditorField showLabel="1" index="20" name="contrast_day_k"/>
        <attributeEditorField showLabel="1" index="21" name="contrast_night_k"/>
        <attributeEditorField showLabel="1" index="22" name="mine_curve_r"/>
        <attributeEditorField showLabel="1" index="23" name="mine_curve_level"/>
        <attributeEditorField showLabel="1" index="19" name="n_scans"/>
      </attributeEditorContainer>
      <attributeEditorContainer columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" name="Shape" visibilityExpression="">
        <attributeEditorField showLabel="1" index="6" name="diameter_m"/>
        <attributeEditorField showLabel="1" index="5" name="area_m2"/>
        <attributeEditorField showLabel="1" index="7" name="circularity"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" name="Contrast curve" visibilityExpression="">
      <attributeEditorContainer columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" name="Contrast curve" visibilityExpression="">
        <attributeEditorField showLabel="1" index="25" name="figure"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" name="Position" visibilityExpression="">
      <attributeEditorContainer columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" name="Position" visibilityExpression="">
        <attributeEditorField showLabel="1" index="1" name="x"/>
        <attributeEditorField showLabel="1" index="2" name="y"/>
        <attributeEditorField showLabel="1" index="3" name="lat"/>
        <attributeEditorField showLabel="1" index="4" name="lon"/>
        <attributeEditorField showLabel="1" index="24" name="fix_quality"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" name="Stored values" visibilityExpression="">
      <attributeEditorContainer columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" name="Stored values" visibilityExpression="">
        <attributeEditorField showLabel="1" index="8" name="depth_m"/>
        <attributeEditorField showLabel="1" index="9" name="depth_sigma_m"/>
        <attributeEditorField showLabel="1" index="10" name="diffusivity_m2s"/>
        <attributeEditorField showLabel="1" index="11" name="diffusivity_sigma_m2s"/>
        <attributeEditorField showLabel="1" index="16" name="p_mine"/>
        <attributeEditorField showLabel="1" index="15" name="cue_confidence"/>
        <attributeEditorField showLabel="1" index="26" name="contrast_series"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
  </attributeEditorForm>
  <editable/>
  <labelOnTop/>
  <reuseLastValue/>
  <dataDefinedFieldProperties/>
  <widgets/>
  <mapTip>&lt;b>[% "short_id" %]&lt;/b> [% "class_cue" %] ([% "status" %])&lt;br/>depth [% "depth" %]&lt;br/>diffusivity [% "diffusivity" %]</mapTip>
  <layerGeometryType>2</layerGeometryType>
</qgis>
